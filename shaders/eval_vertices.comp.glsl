#version 450
// eval.comp.glsl for meshes: position and unit normal only (VertexSample, 32 bytes where
// EvalSample has 64), the same bits as eval.comp's; no κ, and the higher partials only at
// degenerate points. The arithmetic lives in lib/bicubic_eval.h, shared with the fp32 mirror.
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

layout(push_constant) uniform Push { EvalPush pc; };

void main() {
  uint index = linearInvocationIndex();
  if (index >= pc.queryCount) return;
  EvalQuery q = queries[index];
  vertices[index] = evalBicubicVertex(patches[q.patchIndex], q.u, q.v, pc.degenerateEps);
}
