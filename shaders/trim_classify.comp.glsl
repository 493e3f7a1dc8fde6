#version 450
// Quad-tree nodes against trim loops (host/trim/trim_classify_vulkan.cpp), one invocation per
// node: kTrimOutside, kTrimInside or kTrimCrossing. The arithmetic lives in
// lib/trim_classify.h, shared with the fp32 mirror (host/trim/trim_classify_mirror.cpp).
#extension GL_GOOGLE_include_directive : require
#include "layout.h"
#include "lib/shared_glsl_cpp.h"
#include "lib/dispatch.glsl"

layout(std430, binding = 0) readonly buffer Faces { TrimFace faces[]; };
layout(std430, binding = 1) readonly buffer Pieces { TrimPiece pieces[]; };
layout(std430, binding = 2) readonly buffer Segments { vec4 segments[]; };
layout(std430, binding = 3) readonly buffer BinWords { uint binWords[]; };
layout(std430, binding = 4) readonly buffer Queries { TrimQuery queries[]; };
layout(std430, binding = 5) writeonly buffer Results { uint results[]; };

layout(push_constant) uniform Push { TrimPush pc; };

#include "lib/trim_bin.h"
#include "lib/trim_classify.h"

void main() {
  uint index = linearInvocationIndex();
  if (index >= pc.queryCount) return;
  results[index] = classifyTrimNode(queries[index]);
}
