// The setup of SeamVertices (detail/seam_vertices.h): the folded sides and their points, and
// the ids of the positions the leaf walk will weld by. Its lookups (baseKey) are in the header.
#include "mesh/detail/seam_vertices.h"

#include <algorithm>

namespace tessera::triangulate_detail {
namespace {

void sortUnique(std::vector<float>& values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
}

}  // namespace

SeamVertices::SeamVertices(const std::vector<QuadLeaf>& leaves,
                           const std::vector<BezierPatch>& patches,
                           const PatchTopology& topology, bool seamKeys)
    : leaves_(leaves),
      patches_(patches),
      topology_(topology),
      seamKeys_(seamKeys),
      present_(patchesWithLeaves()) {
  findFolds();
}

// The patches with leaves here (all of them, unless a scope passes part of them).
std::vector<bool> SeamVertices::patchesWithLeaves() const {
  std::vector<bool> present(patches_.size(), false);
  for (const QuadLeaf& leaf : leaves_) present[leaf.patchIndex] = true;
  return present;
}

void SeamVertices::findFolds() {
  foldOf_.assign(patches_.size(), {-1, -1, -1, -1});
  for (uint32_t p = 0; p < patches_.size(); ++p)
    for (int side = 0; side < 4 && present_[p]; ++side) {
      const SideInfo& s = topology_.sides[p][side];
      if (s.group >= 0 || s.collapsed) continue;
      // A side of degree 1 (every side of a plane) has two control points, which
      // findSideFold never folds: skipped without building its point list.
      const BezierPatch& bp = patches_[p];
      const int degree = side == kSideV0 || side == kSideV1 ? bp.degreeU : bp.degreeV;
      if (degree + 1 < 3) continue;
      std::optional<SideFold> fold = findSideFold(sideControlPoints(patches_[p], side));
      if (!fold) continue;
      foldOf_[p][side] = int32_t(folds_.size());
      folds_.push_back({std::move(*fold), p, side, {}, {}});
    }
}

// Every corner's point on every strand: the side's ends are the patch corners' vertices (as
// everywhere, welded by position), the rest keyed by their exact position along the line.
void SeamVertices::placeFoldPoints(uint32_t f) {
  FoldedSide& fs = folds_[f];
  // The ends are vertices of every leaf there (onSide gives a patch corner to a v side).
  fs.corners.insert(fs.corners.end(), {0.0f, 1.0f});
  sortUnique(fs.corners);
  const std::vector<glm::dvec3> ends = sideControlPoints(patches_[fs.patch], fs.side);
  const double first = foldCoordinate(fs.fold, 0), last = foldCoordinate(fs.fold, 1);
  const auto keyOf = [&](double s) -> VertexKey {
    if (s == first) return {kPosition, positionId(ends.front()), 0};
    if (s == last) return {kPosition, positionId(ends.back()), 0};
    uint64_t b;
    std::memcpy(&b, &s, sizeof b);
    return {kFoldPosition, f, b};
  };
  for (float t : fs.corners) fs.points.emplace(t, keyOf(foldCoordinate(fs.fold, t)));
  for (float t : fs.corners) {
    const double s = foldCoordinate(fs.fold, t);
    for (double image : foldImages(fs.fold, t, s)) fs.points.emplace(float(image), keyOf(s));
  }
}

void SeamVertices::registerPositions() {
  for (uint32_t p = 0; p < patches_.size(); ++p) {
    if (!present_[p]) continue;
    const BezierPatch& bp = patches_[p];
    for (int j : {0, bp.degreeV})
      for (int i : {0, bp.degreeU}) positionId(bp.at(i, j));
    for (int side = 0; side < 4; ++side)
      if (topology_.sides[p][side].collapsed) positionId(sideStartPoint(bp, side));
  }
  walking_ = true;
}

}  // namespace tessera::triangulate_detail
