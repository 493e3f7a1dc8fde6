// The leaf corners on every line of the leaves (near_points.h, line_index.h): lines u = const
// and v = const of each patch, and each shared side in its canonical parameter. The leaf walk
// reads them as the vertices a leaf edge passes; near-point merging first merges and prunes
// them (near_point_merge.h).
#pragma once
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "mesh/detail/seam_vertices.h"
#include "mesh/line_index.h"

namespace tessera::triangulate_detail {

// The lines a node-based line index was sized for, per leaf (LineIndex::unorderedMapOrder).
constexpr size_t kLineIndexReserve = 2;

// A leaf's four lines, as numbered in LinePoints' indices: v = r.y, v = r.w (in alongU),
// u = r.x, u = r.z (in alongV).
using LeafLines = std::array<uint32_t, 4>;

struct LinePoints {
  LineIndex alongU, alongV;  // lines v = const (points along u) and u = const (along v)
  std::vector<LeafLines> leafLines;  // per leaf: the leaf walk finds its edges' lines by them
  std::vector<std::vector<LinePoint>> shared;  // per group, in canonical parameters
  std::vector<std::pair<uint32_t, int>> groupSide;  // per group, one (patch, side) on it
};

// Every leaf corner with the leaf edges that end there, on each line it is on; the corners on
// a folded side go to its FoldedSide::corners.
LinePoints collectLinePoints(const std::vector<QuadLeaf>& leaves, SeamVertices& seams);

}  // namespace tessera::triangulate_detail
