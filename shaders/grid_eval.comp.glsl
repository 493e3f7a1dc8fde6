#version 450
// Uniform P×P grids of bicubic patches, position and unit normal (GridVertex, 32 bytes):
// one invocation per (patch, row) loads the patch once and writes the row's P vertices.
// The arithmetic lives in lib/grid_eval.h, shared with the fp32 mirror.
#extension GL_GOOGLE_include_directive : require
#include "layout.h"
#include "lib/shared_glsl_cpp.h"
#include "lib/bicubic_eval.h"
#include "lib/grid_eval.h"
#include "lib/dispatch.glsl"

layout(std430, binding = 0) readonly buffer Patches { BicubicPatch patches[]; };
layout(std430, binding = 1) writeonly buffer Vertices { GridVertex vertices[]; };

layout(push_constant) uniform Push { GridEvalPush pc; };

void main() {
  uint index = linearInvocationIndex();
  uint n = pc.pointsPerSide;
  if (index >= pc.patchCount * n) return;
  uint patchIndex = index / n;
  uint i = index - patchIndex * n;
  BicubicPatch bp = patches[patchIndex];
  PRECISE float scale = bicubicScale(bp);
  PRECISE float tol = pc.degenerateEps * scale * scale;
  float u = gridParam(i, n);
  GridRow row = gridRow(bp, u);
  uint base = index * n;
  for (uint j = 0u; j < n; ++j) vertices[base + j] = gridVertex(bp, row, u, gridParam(j, n), tol);
}
