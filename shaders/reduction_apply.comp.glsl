#version 450
// The row product of the control-point reduction (host/reduction/curve_product_vulkan.cpp): invocation
// curve·rows + i writes output point i of one curve, row i of the band matrix applied to it.
// All curves of one direction share the matrix (docs/reduction.md): one dispatch per pass.
#extension GL_GOOGLE_include_directive : require
#include "layout.h"
#include "lib/shared_glsl_cpp.h"
#include "lib/dispatch.glsl"

layout(std430, binding = 0) readonly buffer Firsts { uint firsts[]; };
layout(std430, binding = 1) readonly buffer Offsets { uint offsets[]; };
layout(std430, binding = 2) readonly buffer Weights { float weights[]; };
layout(std430, binding = 3) readonly buffer Points { vec4 points[]; };
layout(std430, binding = 4) writeonly buffer Results { vec4 results[]; };

layout(push_constant) uniform Push { BandApplyPush pc; };

#include "lib/band_apply.h"

void main() {
  uint index = linearInvocationIndex();
  if (index >= pc.curves * pc.rows) return;
  applyBandRow(index / pc.rows, index % pc.rows, pc.rows, pc.cols);
}
