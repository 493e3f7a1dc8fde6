#include "realtime/detail/stitch_mirror.h"

#include <algorithm>

#include "common/glsl_builtins.h"

namespace tessera::mirror {
namespace glsl {
namespace {  // each mirror translation unit gets its own copy of the shared functions
// grid_mirror.cpp's shader headers and stitch_pattern.h: each mirror names the text it compiles.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include "shaders/lib/shared_glsl_cpp.h"
#include "shaders/lib/bicubic_eval.h"
#include "shaders/lib/grid_eval.h"
#include "shaders/lib/stitch_pattern.h"
#pragma GCC diagnostic pop
}  // namespace
}  // namespace glsl

namespace {
void triangle(uint32_t* indices, uint32_t at, uint32_t a, uint32_t b, uint32_t c) {
  indices[3 * at] = a;
  indices[3 * at + 1] = b;
  indices[3 * at + 2] = c;
}
}  // namespace

void stitchItem(const gpu::BicubicPatch* patches, const gpu::StitchPatch* records,
                const gpu::vec4* edgePoints, uint32_t item, float eps, gpu::GridVertex* vertices,
                uint32_t* indices) {
  // The shader's main(), line for line.
  using namespace glsl;
  const gpu::StitchPatch& sp = records[item >> gpu::kStitchSlotBits];
  uint32_t band = item & ((1u << gpu::kStitchSlotBits) - 1u);
  const gpu::BicubicPatch& bp = patches[sp.patchIndex];
  float scale = bicubicScale(bp);
  float tol = eps * scale * scale;
  uint32_t cu = stitchInner(sp.nu);
  uint32_t cv = stitchInner(sp.nv);
  uint32_t v0 = sp.firstVertex;
  uint32_t t0 = sp.firstIndex / 3u;
  uint32_t degenerateFirst = glsl::stitchVertexCount(sp), degenerateLast = 0;
  uint32_t rowEnd = std::min((band + 1) * gpu::kStitchBandRows, cu);
  for (uint32_t i = band * gpu::kStitchBandRows; i < rowEnd; ++i) {
    float u = stitchInnerParam(i, sp.nu);
    GridRow row = gridRow(bp, u);
    for (uint32_t j = 0; j < cv; ++j) {
      GridPoint q = gridRowPoint(row, stitchInnerParam(j, sp.nv));
      vec3 normal;
      if (!gridRegularNormal(q, tol, normal)) {
        degenerateFirst = std::min(degenerateFirst, i * cv + j);
        degenerateLast = i * cv + j;
      }
      vertices[v0 + i * cv + j] = gridPointVertex(bp, q, normal);
    }
    if (i + 1 < cu) {
      for (uint32_t j = 0; j + 1 < cv; ++j) {
        uint32_t a = v0 + i * cv + j;
        uint32_t at = t0 + 2 * (i * (cv - 1) + j);
        triangle(indices, at, a, a + cv, a + cv + 1);
        triangle(indices, at + 1, a, a + cv + 1, a + 1);
      }
    }
  }
  uint32_t sides = rowEnd == cu ? 4 : 0;
  for (uint32_t s = 0; s < sides; ++s) {
    uint32_t e = sp.sideSegments[s];
    uint32_t edge = sp.sideEdge[s];
    uint32_t local = stitchSideFirstVertex(sp, s);
    uint32_t first = v0 + local;
    bool column = (s & 1) == 0;
    vec2 end = stitchSideUV(sp, s, 0);
    GridRow side = gridCurves(bp, column ? end.y : end.x, column);
    vec4 e0 = edgePoints[4 * edge];
    vec4 e1 = edgePoints[4 * edge + 1];
    vec4 e2 = edgePoints[4 * edge + 2];
    vec4 e3 = edgePoints[4 * edge + 3];
    for (uint32_t k = 0; k <= e; ++k) {
      vec2 uv = stitchSideUV(sp, s, k);
      GridPoint q = gridCurvesPoint(side, column ? uv.x : uv.y, column);
      vec3 normal;
      if (!gridRegularNormal(q, tol, normal)) {
        degenerateFirst = std::min(degenerateFirst, local + k);
        degenerateLast = local + k;
      }
      GridVertex g = gridPointVertex(bp, q, normal);
      g.position = vec4(stitchSidePosition(sp, s, k, e0, e1, e2, e3), 1.0f);
      vertices[first + k] = g;
    }
    uint32_t n = stitchSideCount(sp, s);
    uint32_t c = stitchInner(n);
    bool flip = s >= 2;
    bool collapsed = (sp.sideFlags[s] & gpu::kStitchCollapsed) != 0;
    uint32_t at = t0 + stitchSideFirstTriangle(sp, s);
    uint32_t i = 0, k = 0;
    while (k < e || i + 1 < c) {
      uint32_t a = first + k;
      uint32_t d = v0 + stitchInnerAlongSide(sp, s, i);
      uint32_t b;
      if (stitchAdvanceOuter(k, e, i, c, n)) {
        b = first + k + 1;
        k = k + 1;
        if (collapsed) continue;
      } else {
        b = v0 + stitchInnerAlongSide(sp, s, i + 1);
        i = i + 1;
      }
      if (flip)
        triangle(indices, at, a, d, b);
      else
        triangle(indices, at, a, b, d);
      at = at + 1;
    }
  }
  for (uint32_t local = degenerateFirst; local <= degenerateLast; ++local) {
    StitchVertexCurve at = stitchVertexCurve(sp, local);
    GridRow curves = gridCurves(bp, at.fixedParam, at.column);
    vec3 normal;
    if (!gridRegularNormal(gridCurvesPoint(curves, at.along, at.column), tol, normal))
      vertices[v0 + local].normal = vec4(gridDegenerateNormal(bp, at.uv.x, at.uv.y, tol), 0.0f);
  }
}

uint32_t stitchVertexCount(const gpu::StitchPatch& record) {
  return glsl::stitchVertexCount(record);
}
uint32_t stitchTriangleCount(const gpu::StitchPatch& record) {
  return glsl::stitchTriangleCount(record);
}
uint32_t stitchItemCount(const gpu::StitchPatch& record) {
  return (glsl::stitchInner(record.nu) + gpu::kStitchBandRows - 1) / gpu::kStitchBandRows;
}

uint32_t stitchSideVertex(const gpu::StitchPatch& record, uint32_t side, uint32_t k) {
  return glsl::stitchSideFirstVertex(record, side) + k;
}

std::vector<gpu::vec2> stitchVertexParams(const gpu::StitchPatch& sp) {
  using namespace glsl;
  std::vector<gpu::vec2> uv(glsl::stitchVertexCount(sp));
  const uint32_t cu = stitchInner(sp.nu), cv = stitchInner(sp.nv);
  for (uint32_t i = 0; i < cu; ++i)
    for (uint32_t j = 0; j < cv; ++j)
      uv[i * cv + j] = {stitchInnerParam(i, sp.nu), stitchInnerParam(j, sp.nv)};
  for (uint32_t s = 0; s < 4; ++s)
    for (uint32_t k = 0; k <= sp.sideSegments[s]; ++k)
      uv[stitchSideFirstVertex(sp, s) + k] = stitchSideUV(sp, s, k);
  return uv;
}

}  // namespace tessera::mirror
