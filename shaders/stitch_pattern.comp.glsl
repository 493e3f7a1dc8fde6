#version 450
// The stitched pattern of every visible patch (lib/stitch_pattern.h, docs/realtime.md): one
// invocation per work item, an inner-grid row (its vertices and the cells below the next row)
// or a side (its edge points and its transition strip). Positions of edge points come from the
// edge's canonical control points, so the two patches of a shared edge write the same bits.
// Indices are global (firstVertex added): the index buffer is ready to draw.
// The mirror is host/realtime/stitch_mirror.cpp, line for line.
#extension GL_GOOGLE_include_directive : require
#include "layout.h"
#include "lib/shared_glsl_cpp.h"
#include "lib/bicubic_eval.h"
#include "lib/grid_eval.h"
#include "lib/stitch_pattern.h"
#include "lib/dispatch.glsl"

layout(std430, binding = 0) readonly buffer Patches { BicubicPatch patches[]; };
layout(std430, binding = 1) readonly buffer Records { StitchPatch records[]; };
layout(std430, binding = 2) readonly buffer Edges { vec4 edgePoints[]; };
layout(std430, binding = 3) readonly buffer Items { uint items[]; };
layout(std430, binding = 4) writeonly buffer Vertices { GridVertex vertices[]; };
layout(std430, binding = 5) writeonly buffer Indices { uint indices[]; };

layout(push_constant) uniform Push { StitchPush pc; };

void triangle(uint at, uint a, uint b, uint c) {
  indices[3u * at] = a;
  indices[3u * at + 1u] = b;
  indices[3u * at + 2u] = c;
}

void main() {
  uint index = linearInvocationIndex();
  if (index >= pc.itemCount) return;
  uint item = items[index];
  StitchPatch sp = records[item >> kStitchSlotBits];
  uint slot = item & ((1u << kStitchSlotBits) - 1u);
  BicubicPatch bp = patches[sp.patchIndex];
  PRECISE float scale = bicubicScale(bp);
  PRECISE float tol = pc.degenerateEps * scale * scale;
  uint cu = stitchInner(sp.nu);
  uint cv = stitchInner(sp.nv);
  uint v0 = sp.firstVertex;
  uint t0 = sp.firstIndex / 3u;
  // A degenerate point (a pole: |Pu × Pv| ≤ tol) takes bicubicNormal's full rule, ~4× a
  // vertex's arithmetic. A CPU driver runs both sides of a branch in every SIMD lane, so that
  // rule runs in a second loop over the range of degenerate points only (usually empty).
  if (slot < cu) {  // inner row i: its vertices, then the cells between it and row i + 1
    uint i = slot;
    float u = stitchInnerParam(i, sp.nu);
    GridRow row = gridRow(bp, u);
    uint rowFirst = v0 + i * cv;
    uint degenerateFirst = cv;
    uint degenerateLast = 0u;
    for (uint j = 0u; j < cv; ++j) {
      GridPoint q = gridRowPoint(row, stitchInnerParam(j, sp.nv));
      vec3 normal;
      if (!gridRegularNormal(q, tol, normal)) {
        degenerateFirst = min(degenerateFirst, j);
        degenerateLast = j;
      }
      vertices[rowFirst + j] = gridPointVertex(bp, q, normal);
    }
    for (uint j = degenerateFirst; j <= degenerateLast; ++j) {
      float v = stitchInnerParam(j, sp.nv);
      vec3 normal;
      if (!gridRegularNormal(gridRowPoint(row, v), tol, normal))
        vertices[rowFirst + j].normal = vec4(gridDegenerateNormal(bp, u, v, tol), 0.0f);
    }
    if (i + 1u < cu) {
      for (uint j = 0u; j + 1u < cv; ++j) {
        uint a = rowFirst + j;
        uint at = t0 + 2u * (i * (cv - 1u) + j);
        triangle(at, a, a + cv, a + cv + 1u);
        triangle(at + 1u, a, a + cv + 1u, a + 1u);
      }
    }
    return;
  }
  uint s = slot - cu;
  uint e = sp.sideSegments[s];
  uint edge = sp.sideEdge[s];
  uint first = v0 + stitchSideFirstVertex(sp, s);
  // Sides V0, V1 (v = 0, 1) take a column, U0, U1 (u = 0, 1) a row: one for all their points.
  bool column = (s & 1u) == 0u;
  vec2 end = stitchSideUV(sp, s, 0u);
  GridRow side = gridCurves(bp, column ? end.y : end.x, column);
  // The edge's canonical control points, read once for all its points.
  vec4 e0 = edgePoints[4u * edge];
  vec4 e1 = edgePoints[4u * edge + 1u];
  vec4 e2 = edgePoints[4u * edge + 2u];
  vec4 e3 = edgePoints[4u * edge + 3u];
  uint degenerateFirst = e + 1u;
  uint degenerateLast = 0u;
  for (uint k = 0u; k <= e; ++k) {
    vec2 uv = stitchSideUV(sp, s, k);
    GridPoint q = gridCurvesPoint(side, column ? uv.x : uv.y, column);
    vec3 normal;
    if (!gridRegularNormal(q, tol, normal)) {
      degenerateFirst = min(degenerateFirst, k);
      degenerateLast = k;
    }
    GridVertex g = gridPointVertex(bp, q, normal);
    g.position = vec4(stitchSidePosition(sp, s, k, e0, e1, e2, e3), 1.0f);
    vertices[first + k] = g;
  }
  for (uint k = degenerateFirst; k <= degenerateLast; ++k) {
    vec2 uv = stitchSideUV(sp, s, k);
    vec3 normal;
    if (!gridRegularNormal(gridCurvesPoint(side, column ? uv.x : uv.y, column), tol, normal))
      vertices[first + k].normal = vec4(gridDegenerateNormal(bp, uv.x, uv.y, tol), 0.0f);
  }
  // The zipper: edge points o_k (outside) and inner vertices n_i, counter-clockwise in (u, v):
  // sides V0 and U1 have the edge on the right of increasing t, V1 and U0 on the left.
  uint n = stitchSideCount(sp, s);
  uint c = stitchInner(n);
  bool flip = s >= 2u;
  bool collapsed = (sp.sideFlags[s] & kStitchCollapsed) != 0u;
  uint at = t0 + stitchSideFirstTriangle(sp, s);
  uint i = 0u;
  uint k = 0u;
  while (k < e || i + 1u < c) {
    // Outer step (o_k, o_k+1, n_i) or inner step (o_k, n_i+1, n_i): counter-clockwise for V0
    // and U1, reversed for V1 and U0.
    uint a = first + k;
    uint d = v0 + stitchInnerAlongSide(sp, s, i);
    uint b;
    if (stitchAdvanceOuter(k, e, i, c, n)) {
      b = first + k + 1u;
      k = k + 1u;
      if (collapsed) continue;
    } else {
      b = v0 + stitchInnerAlongSide(sp, s, i + 1u);
      i = i + 1u;
    }
    if (flip)
      triangle(at, a, d, b);
    else
      triangle(at, a, b, d);
    at = at + 1u;
  }
}
