#version 450
// eval.comp.glsl for general patches (degree 1..7 each way, polynomial or rational): position,
// Pu, Pv, unit normal and κ for a batch of (patch, u, v) queries. The arithmetic lives in
// lib/general_eval.h, shared with the fp32 mirror.
#extension GL_GOOGLE_include_directive : require
#include "layout.h"
#include "lib/shared_glsl_cpp.h"

layout(std430, binding = 0) readonly buffer Patches { GeneralPatch patches[]; };
layout(std430, binding = 1) readonly buffer Queries { EvalQuery queries[]; };
layout(std430, binding = 2) writeonly buffer Samples { EvalSample samples[]; };
layout(std430, binding = 3) readonly buffer Points { vec4 controlPoints[]; };

#include "lib/bicubic_eval.h"
#include "lib/general_eval.h"
#include "lib/dispatch.glsl"

layout(push_constant) uniform Push { EvalPush pc; };

void main() {
  uint index = linearInvocationIndex();
  if (index >= pc.queryCount) return;
  EvalQuery q = queries[index];
  samples[index] = evalGeneralSample(patches[q.patchIndex], q.u, q.v, pc.degenerateEps);
}
