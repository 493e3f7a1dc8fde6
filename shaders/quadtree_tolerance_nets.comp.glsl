#version 450
// Rule T on bicubic patches, first of two dispatches a level: per node, the terms (largest
// norm, error term, centre, spread) of two of the three restricted second-difference nets (Δ²_s and Δ_sΔ_t: lib/tolerance_bound.h,
// bicubicNetBound) into ToleranceNetBounds; quadtree_tolerance.comp.glsl adds the third and
// decides. Why two shaders: lavapipe compiles every pipeline at every run, on the thread that
// asks, and the nets' de Casteljau restrictions are most of the compile: two pipelines built
// on two threads take about half the time of one (bench/bench_startup.cpp). The same text as
// the mirror's bicubicSecondBounds, net by net, so the decisions are bit-identical.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "lib/tolerance_bicubic_shader.glsl"  // bindings 0-1, push constants

layout(std430, binding = 2) writeonly buffer Nets { ToleranceNetBounds nets[]; };

void main() {
  uint index = linearInvocationIndex();
  if (index >= pc.nodeCount) return;
  QuadNode node = fetchNode(index);
  BicubicPatch bp = fetchPatch(node.patchIndex);
  float ssError;
  float stError;
  NetTerms ss = bicubicNetBound(bp, node.rect, 0, ssError);
  NetTerms st = bicubicNetBound(bp, node.rect, 1, stError);
  nets[index].ssSt = vec4(ss.largest, ssError, st.largest, stError);
  nets[index].ssCentre = netCentreSpread(ss);
  nets[index].stCentre = netCentreSpread(st);
}
