#version 450
// eval.comp.glsl for meshes: position and unit normal only (VertexSample, 32 bytes where
// EvalSample has 64), the same bits as eval.comp's; no κ, and the higher partials only at
// degenerate points. One invocation per run of consecutive queries on one patch (VertexEvalPush,
// layout.h): the patch is read once a run. The arithmetic lives in lib/bicubic_eval.h, shared
// with the fp32 mirror (a vertex's bits do not depend on its run).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "layout.h"
#include "lib/shared_glsl_cpp.h"
#define BICUBIC_EVAL_UNROLL [[unroll]]  // constant trip counts: lib/bicubic_eval.h
#include "lib/bicubic_eval.h"
#include "lib/dispatch.glsl"

layout(std430, binding = 0) readonly buffer Patches { BicubicPatch patches[]; };
layout(std430, binding = 1) readonly buffer Queries { EvalQuery queries[]; };
layout(std430, binding = 2) writeonly buffer Vertices { VertexSample vertices[]; };
layout(std430, binding = 3) readonly buffer Runs { uint runStarts[]; };

layout(push_constant) uniform Push { VertexEvalPush pc; };

void main() {
  uint run = linearInvocationIndex();
  if (run >= pc.runCount) return;
  uint first = runStarts[run];
  uint end = runStarts[run + 1u];
  BicubicPatch bp = patches[queries[first].patchIndex];
  float tol = bicubicTolerance(bp, pc.degenerateEps);
  for (uint i = first; i < end; ++i) {
    EvalQuery q = queries[i];
    vertices[i] = bicubicVertex(bp, q.u, q.v, tol);
  }
}
