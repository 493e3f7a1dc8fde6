#version 450
// Applies one batch of a Loop stencil table: invocation i computes row sourceRows +
// firstStencil + i from rows written by earlier batches (or given by the host). The host runs
// the batches in order with a compute-to-compute barrier between them.
#extension GL_GOOGLE_include_directive : require
#include "layout.h"
#include "lib/shared_glsl_cpp.h"
#include "lib/dispatch.glsl"

layout(std430, binding = 0) readonly buffer Offsets { uint offsets[]; };
layout(std430, binding = 1) readonly buffer Indices { uint indices[]; };
layout(std430, binding = 2) readonly buffer Weights { float weights[]; };
layout(std430, binding = 3) buffer Values { float values[]; };

layout(push_constant) uniform Push { LoopStencilPush pc; };

#include "lib/stencil_apply.h"

void main() {
  uint index = linearInvocationIndex();
  if (index >= pc.stencilCount) return;
  applyStencil(pc.firstStencil + index, pc.sourceRows, pc.width);
}
