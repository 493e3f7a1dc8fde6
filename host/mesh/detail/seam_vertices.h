// Which vertex a point (u, v) of a patch is, across the patches (docs/watertight.md): a patch
// corner, or any point of a collapsed side (a pole), by its exact control-point position; a
// point of a shared side by its canonical parameter (shared_edges.h); a point of a side that
// folds back on itself (side_fold.h) by its position along the fold's line; anything else by
// (patch, u, v). The triangulator's setup and its leaf walk both ask (baseKey), the walk once
// per leaf corner and edge point: baseKey and positionId stay inline here for it.
#pragma once
#include <array>
#include <cstring>
#include <map>
#include <stdexcept>
#include <vector>

#include "common/hash_map.h"
#include "mesh/detail/vertex_key.h"
#include "mesh/shared_edges.h"
#include "mesh/side_fold.h"
#include "mesh/triangulate.h"

namespace tessera::triangulate_detail {

// A point's parameter along shared side s, in the side group's own direction (both patches on
// the side see the same value).
inline float canonical(const SideInfo& s, float t) { return s.reversed ? 1.0f - t : t; }

// Which side of the parameter square (u, v) lies on, and the parameter t along it.
inline bool onSide(float u, float v, int& side, float& t) {
  if (v == 0.0f) return side = kSideV0, t = u, true;
  if (v == 1.0f) return side = kSideV1, t = u, true;
  if (u == 0.0f) return side = kSideU0, t = v, true;
  if (u == 1.0f) return side = kSideU1, t = v, true;
  return false;
}

struct PositionBitsHash {
  size_t operator()(const std::array<uint64_t, 3>& k) const {
    return size_t(k[0] * 0x9E3779B97F4A7C15ull ^ k[1] * 0xC2B2AE3D27D4EB4Full ^
                  (k[2] ^ k[2] >> 29) * 0x165667B19E3779F9ull);
  }
};

// A side that folds back over itself (side_fold.h) and is no other patch's: over the part
// it retraces, both strands are one curve, so every point on one strand is also a vertex on
// the others, identified by its position along the fold's line (docs/watertight.md).
struct FoldedSide {
  SideFold fold;
  uint32_t patch;
  int side;
  std::vector<float> corners;         // leaf corners on the side (t), from collectLinePoints
  std::map<float, VertexKey> points;  // t → vertex: the corners and their images
};

class SeamVertices {
 public:
  // Finds the folded sides of the patches with leaves.
  SeamVertices(const std::vector<QuadLeaf>& leaves, const std::vector<BezierPatch>& patches,
               const PatchTopology& topology, bool seamKeys);

  const std::vector<BezierPatch>& patches() const { return patches_; }
  const PatchTopology& topology() const { return topology_; }
  // Per patch side, its index in the folded sides, or -1.
  int32_t foldOf(uint32_t patch, int side) const { return foldOf_[patch][side]; }
  size_t foldCount() const { return folds_.size(); }
  FoldedSide& fold(uint32_t f) { return folds_[f]; }
  const FoldedSide& fold(uint32_t f) const { return folds_[f]; }

  // Once the fold's corners are collected: every corner's point on every strand.
  void placeFoldPoints(uint32_t f);

  // Gives an id to every position baseKey can meet in the leaf walk (the corners of each
  // patch with leaves, and its collapsed sides' points); from here on positions are only
  // looked up, so the walk may ask on several threads. Ids only tell positions apart from
  // here on: merging, where their order counts, is done.
  void registerPositions();

  // The key of the vertex at (u, v) of `patch` before merging near points: patch corners and
  // collapsed sides by position, shared sides by canonical parameter, folded sides by their
  // fold's point, anything else by (patch, u, v).
  VertexKey baseKey(uint32_t patch, float u, float v) {
    const BezierPatch& bp = patches_[patch];
    bool uEnd = u == 0.0f || u == 1.0f, vEnd = v == 0.0f || v == 1.0f;
    if (uEnd && vEnd) {
      const glm::dvec3& corner = bp.at(u == 0.0f ? 0 : bp.degreeU, v == 0.0f ? 0 : bp.degreeV);
      return {kPosition, positionId(corner), 0};
    }
    int side;
    float t;
    if (onSide(u, v, side, t)) {
      const SideInfo& s = topology_.sides[patch][side];
      if (s.collapsed) return {kPosition, positionId(sideStartPoint(bp, side)), 0};
      if (s.group >= 0) return {kEdgeParam, uint32_t(s.group), bits(canonical(s, t))};
      if (const int32_t f = foldOf_[patch][side]; f >= 0) {
        auto it = folds_[f].points.find(t);
        if (it != folds_[f].points.end()) return it->second;
      }
    }
    return {kPatchParam, patch, (uint64_t(bits(u)) << 32) | bits(v)};
  }

  // Ids in the order positions are first met (near_point_merge.cpp's ranksBefore compares them).
  uint32_t positionId(const glm::dvec3& p) {
    std::array<uint64_t, 3> key;
    for (int c = 0; c < 3; ++c) {
      double x = p[c] == 0.0 ? 0.0 : p[c];
      std::memcpy(&key[c], &x, sizeof x);
    }
    if (walking_) {  // read only: registerPositions listed every position the walk meets
      const auto found = positions_.find(key);
      if (found == positions_.end())
        throw std::logic_error("triangulateLeaves: a position met by the walk was not listed");
      return found->second;
    }
    const auto [id, inserted] = positions_.try_emplace(key, uint32_t(positions_.size()));
    if (inserted && seamKeys_) positionPoints_.push_back(p);
    return id->second;
  }

  // How another triangulation of the same patches names the vertex (SeamKey).
  SeamKey seamKeyOf(const VertexKey& key) const {
    if (key.kind == kEdgeParam) return {SeamKey::kSharedSide, key.a, uint32_t(key.b), {}};
    if (key.kind == kPosition) return {SeamKey::kPosition, 0, 0, positionPoints_[key.a]};
    return {};  // a point of one patch, or of its folded side (never shared: findFolds)
  }

 private:
  std::vector<bool> patchesWithLeaves() const;
  void findFolds();

  const std::vector<QuadLeaf>& leaves_;
  const std::vector<BezierPatch>& patches_;
  const PatchTopology& topology_;
  const bool seamKeys_;
  const std::vector<bool> present_;  // per patch, whether it has leaves here
  std::vector<std::array<int32_t, 4>> foldOf_;  // per patch side, index in folds_ or -1
  std::vector<FoldedSide> folds_;
  bool walking_ = false;  // the leaves are being walked: positions are only looked up
  HashMap<std::array<uint64_t, 3>, uint32_t, PositionBitsHash> positions_;
  std::vector<glm::dvec3> positionPoints_;  // by position id, for seam keys
};

}  // namespace tessera::triangulate_detail
