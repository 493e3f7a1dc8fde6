#version 450
// Rule T on bicubic patches, second of two dispatches a level: the third restricted net's terms
// (Δ²_t), with the two quadtree_tolerance_nets.comp.glsl wrote, give the node's proven bound
// (lib/tolerance_bound.h), and toleranceDecision decides against δ. Without the corner frames
// and rules B-D's tests, which quadtree.comp.glsl has: the driver compiles the pipeline at
// every run (lavapipe keeps no pipeline cache), and this default job's shaders should cost it
// as little as they can. The mirror's text, so the decisions are bit-identical.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "lib/tolerance_bicubic_shader.glsl"  // bindings 0-1, push constants

// The first dispatch's ToleranceNetBounds, 3 texels a node.
layout(binding = 2) uniform usamplerBuffer netTexels;
layout(std430, binding = 3) writeonly buffer Decisions { NodeDecision decisions[]; };

void main() {
  uint index = linearInvocationIndex();
  if (index >= pc.nodeCount) return;
  QuadNode node = fetchNode(index);
  ToleranceNetBounds first;
  first.ssSt = fetchVec4(netTexels, 3u * index);
  first.ssCentre = fetchVec4(netTexels, 3u * index + 1u);
  first.stCentre = fetchVec4(netTexels, 3u * index + 2u);
  vec3 errors;
  errors.xy = first.ssSt.yw;
  NetTerms tt = bicubicNetBound(fetchPatch(node.patchIndex), node.rect, 2, errors.z);
  ToleranceTerms terms = bicubicTermsOfNets(netTermsOf(first.ssCentre, first.ssSt.x),
                                            netTermsOf(first.stCentre, first.ssSt.z), tt, errors,
                                            node.rect);
  decisions[index] = toleranceDecision(terms, node, pc);
}
