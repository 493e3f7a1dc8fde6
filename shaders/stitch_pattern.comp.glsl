#version 450
// The stitched pattern of every visible patch (lib/stitch_pattern.h, docs/realtime.md): one
// invocation per work item, a band of up to kStitchBandRows inner rows of a patch (most patches
// are one band) and, in its last band, the four sides' edge points and transition strips. One
// invocation per patch reads the patch and its record once (on lavapipe every buffer read is a
// loop over the SIMD lanes); the bands bound an invocation's serial work on a GPU. Positions of
// edge points come from the edge's canonical control points, so the two patches of a shared
// edge write the same bits.
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
  uint band = item & ((1u << kStitchSlotBits) - 1u);
  BicubicPatch bp = patches[sp.patchIndex];
  PRECISE float scale = bicubicScale(bp);
  PRECISE float tol = pc.degenerateEps * scale * scale;
  uint cu = stitchInner(sp.nu);
  uint cv = stitchInner(sp.nv);
  uint v0 = sp.firstVertex;
  uint t0 = sp.firstIndex / 3u;
  // A degenerate point (a pole: |Pu × Pv| ≤ tol) takes bicubicNormal's full rule, ~4× a
  // vertex's arithmetic. A CPU driver runs both sides of a branch in every SIMD lane, so that
  // rule runs last, in a loop over the range of the patch's degenerate points only (local
  // vertex numbers; usually empty).
  uint degenerateFirst = stitchVertexCount(sp);
  uint degenerateLast = 0u;
  // The band's inner rows, one by one: a row's vertices, then the cells between it and row
  // i + 1 (whose vertices the next band may write: the indices need only its numbers).
  uint rowEnd = min((band + 1u) * kStitchBandRows, cu);
  for (uint i = band * kStitchBandRows; i < rowEnd; ++i) {
    float u = stitchInnerParam(i, sp.nu);
    GridRow row = gridRow(bp, u);
    for (uint j = 0u; j < cv; ++j) {
      GridPoint q = gridRowPoint(row, stitchInnerParam(j, sp.nv));
      vec3 normal;
      if (!gridRegularNormal(q, tol, normal)) {
        degenerateFirst = min(degenerateFirst, i * cv + j);
        degenerateLast = i * cv + j;
      }
      vertices[v0 + i * cv + j] = gridPointVertex(bp, q, normal);
    }
    if (i + 1u < cu) {
      for (uint j = 0u; j + 1u < cv; ++j) {
        uint a = v0 + i * cv + j;
        uint at = t0 + 2u * (i * (cv - 1u) + j);
        triangle(at, a, a + cv, a + cv + 1u);
        triangle(at + 1u, a, a + cv + 1u, a + 1u);
      }
    }
  }
  // The last band: the sides, each one's edge points, then its transition strip.
  uint sides = rowEnd == cu ? 4u : 0u;
  for (uint s = 0u; s < sides; ++s) {
    uint e = sp.sideSegments[s];
    uint edge = sp.sideEdge[s];
    uint local = stitchSideFirstVertex(sp, s);
    uint first = v0 + local;
    // Sides V0, V1 (v = 0, 1) take a column, U0, U1 (u = 0, 1) a row: one for all their points.
    bool column = (s & 1u) == 0u;
    vec2 end = stitchSideUV(sp, s, 0u);
    GridRow side = gridCurves(bp, column ? end.y : end.x, column);
    // The edge's canonical control points, read once for all its points.
    vec4 e0 = edgePoints[4u * edge];
    vec4 e1 = edgePoints[4u * edge + 1u];
    vec4 e2 = edgePoints[4u * edge + 2u];
    vec4 e3 = edgePoints[4u * edge + 3u];
    for (uint k = 0u; k <= e; ++k) {
      vec2 uv = stitchSideUV(sp, s, k);
      GridPoint q = gridCurvesPoint(side, column ? uv.x : uv.y, column);
      vec3 normal;
      if (!gridRegularNormal(q, tol, normal)) {
        degenerateFirst = min(degenerateFirst, local + k);
        degenerateLast = local + k;
      }
      GridVertex g = gridPointVertex(bp, q, normal);
      g.position = vec4(stitchSidePosition(sp, s, k, e0, e1, e2, e3), 1.0f);
      vertices[first + k] = g;
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
  // The degenerate points' normals: each point's row or column again (the same arithmetic as
  // above), and bicubicNormal's full rule where |Pu × Pv| ≤ tol.
  for (uint local = degenerateFirst; local <= degenerateLast; ++local) {
    StitchVertexCurve at = stitchVertexCurve(sp, local);
    GridRow curves = gridCurves(bp, at.fixedParam, at.column);
    vec3 normal;
    if (!gridRegularNormal(gridCurvesPoint(curves, at.along, at.column), tol, normal))
      vertices[v0 + local].normal = vec4(gridDegenerateNormal(bp, at.uv.x, at.uv.y, tol), 0.0f);
  }
}
