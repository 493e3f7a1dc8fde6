#version 450
// Division counts (N_u, N_v) of rational Bézier patches, one invocation per patch: the split
// method in fp32 (docs/rational_division.md). The arithmetic lives in lib/division_count.h,
// shared with the fp32 mirror (host/division/count_mirror.cpp).
#extension GL_GOOGLE_include_directive : require
#include "layout.h"
#include "lib/shared_glsl_cpp.h"
#include "lib/division_count.h"
#include "lib/dispatch.glsl"

layout(std430, binding = 0) readonly buffer Patches { DivisionPatch patches[]; };
layout(std430, binding = 1) readonly buffer Points { vec4 points[]; };
layout(std430, binding = 2) writeonly buffer Results { DivisionResult results[]; };

layout(push_constant) uniform Push { DivisionPush pc; };

void main() {
  uint index = linearInvocationIndex();
  if (index >= pc.patchCount) return;
  DivisionPatch p = patches[index];
  gNet.n = int(p.degreeU);
  gNet.m = int(p.degreeV);
  int count = (gNet.n + 1) * (gNet.m + 1);
  for (int k = 0; k < count; ++k) gNet.h[k] = points[p.firstPoint + uint(k)];
  results[index] = divisionCounts(pc);
}
