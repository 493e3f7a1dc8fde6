// The leaf corners on every line of the leaves (near_points.h, line_index.h): lines u = const
// and v = const of each patch, and each shared side in its canonical parameter. The leaf walk
// reads them as the vertices a leaf edge passes; near-point merging first merges and prunes
// them (near_point_merge.h).
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "mesh/detail/seam_vertices.h"
#include "mesh/line_index.h"

namespace tessera::triangulate_detail {

// The lines a node-based line index was sized for, per leaf (LineIndex::unorderedMapOrder).
constexpr size_t kLineIndexReserve = 2;

// A leaf's two lines in one of LinePoints' indices, as numbered there: v = r.y, v = r.w in
// alongU; u = r.x, u = r.z in alongV.
using LeafLines = std::array<uint32_t, 2>;

struct LinePoints {
  LineIndex alongU, alongV;  // lines v = const (points along u) and u = const (along v)
  // Per leaf, its lines in alongU and alongV: the leaf walk finds its edges' lines by them.
  std::vector<LeafLines> leafLinesU, leafLinesV;
  std::vector<std::vector<LinePoint>> shared;  // per group, in canonical parameters
  std::vector<std::pair<uint32_t, int>> groupSide;  // per group, one (patch, side) on it
};

// What collectLinePoints has filled when it calls its hook: the lines of one direction, or
// the shared sides' points (LinePoints::shared and groupSide).
enum class LineSet { kAlongU, kAlongV, kSharedSides };

// Every leaf corner with the leaf edges that end there, on each line it is on; the corners on
// a folded side go to its FoldedSide::corners. The two directions on up to 2 of `threads`
// (0: all); the same lines whatever the count. `filled(lines, set)`, if given, runs once per
// direction, on the thread that filled it, once it is filled (it may read and change those
// lines only): work of one set rides along without another hand-off to the threads. The
// shared sides' call follows a direction's on each thread that finds the sides' points in:
// calls may overlap and repeat, the callee shares the work out.
LinePoints collectLinePoints(const std::vector<QuadLeaf>& leaves, SeamVertices& seams,
                             unsigned threads,
                             const std::function<void(LinePoints&, LineSet)>& filled = {});

}  // namespace tessera::triangulate_detail
