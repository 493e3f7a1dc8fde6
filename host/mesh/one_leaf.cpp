// triangulateOneLeaf (detail/one_leaf.h): the one-leaf tree's mesh without the general setup.
#include "mesh/detail/one_leaf.h"

#include <array>
#include <cmath>

#include "mesh/shared_edges.h"
#include "mesh/side_fold.h"

namespace tessera::triangulate_detail {

std::optional<ParamMesh> triangulateOneLeaf(const std::vector<QuadLeaf>& leaves,
                                            const std::vector<BezierPatch>& patches,
                                            const TriangulationScope& scope) {
  if (leaves.size() != 1 || patches.size() != 1 || scope.topology || scope.seamKeys ||
      scope.firstPatch > 0 || scope.endPatch < 1)
    return std::nullopt;
  const QuadLeaf& leaf = leaves[0];
  const gpu::vec4& r = leaf.rect;
  if (leaf.patchIndex != 0 || r.x != 0.0f || r.y != 0.0f || r.z != 1.0f || r.w != 1.0f)
    return std::nullopt;
  // The walk's two triangles (0, 1, 2), (0, 2, 3) keep to the main diagonal.
  if (leaf.diagonal != gpu::kToleranceAnyDiagonal && leaf.diagonal != gpu::kToleranceMainDiagonal)
    return std::nullopt;
  const BezierPatch& patch = patches[0];
  const int n = patch.degreeU, m = patch.degreeV;
  // Ring order: (0, 0), (1, 0), (1, 1), (0, 1).
  const std::array<glm::dvec3, 4> corners = {patch.at(0, 0), patch.at(n, 0), patch.at(n, m),
                                             patch.at(0, m)};
  // Distinct by value (== treats −0 as 0, as the walk's position keys do); finite, so that
  // value and bits agree.
  for (size_t a = 0; a < 4; ++a) {
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(corners[a][c])) return std::nullopt;
    for (size_t b = a + 1; b < 4; ++b)
      if (corners[a] == corners[b]) return std::nullopt;
  }
  // Two sides share a curve only if they share its end points, and a collapsed side has equal
  // ends: with distinct corners neither happens. A fold (side_fold.h) needs three points.
  for (int side = 0; side < 4; ++side) {
    const int degree = side == kSideV0 || side == kSideV1 ? n : m;
    if (degree + 1 >= 3 && findSideFold(sideControlPoints(patch, side))) return std::nullopt;
  }
  ParamMesh mesh;
  mesh.vertices = {{0, 0.0f, 0.0f}, {0, 1.0f, 0.0f}, {0, 1.0f, 1.0f}, {0, 0.0f, 1.0f}};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  mesh.trianglePatch = {0, 0};
  mesh.cornerUv = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f},
                   {0.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
  return mesh;
}

}  // namespace tessera::triangulate_detail
