// collectLinePoints (detail/line_points.h): puts each leaf corner on its lines, before near
// points are merged and the leaves walked. The leaves' lines are numbered first, so that each
// line's room in LineIndex's one array is known before it is filled.
#include "mesh/detail/line_points.h"

#include <atomic>

#include "common/parallel_for.h"

namespace tessera::triangulate_detail {
namespace {

// Numbers the leaves' lines in one direction (alongU: v = r.y, v = r.w; else u = r.x,
// u = r.z), each looked up once, in the order the leaves' corners meet them (the lines'
// numbers follow it; a line's points are sorted before use, their order free).
std::vector<LeafLines> numberLeafLines(const std::vector<QuadLeaf>& leaves, bool alongU,
                                       LineIndex& index) {
  std::vector<LeafLines> leafLines(leaves.size());
  // Consecutive leaves mostly share lines (a row's leaves both of theirs along u, a leaf's
  // left line its left neighbour's right one): the last leaf's two are asked first.
  uint64_t lastKeys[2] = {UINT64_MAX, UINT64_MAX};
  LeafLines last = {0, 0};
  const auto number = [&](uint64_t key) {
    for (int k = 0; k < 2; ++k)
      if (key == lastKeys[k]) return last[k];
    return index.number(key);
  };
  for (size_t l = 0; l < leaves.size(); ++l) {
    const gpu::vec4& r = leaves[l].rect;
    const uint32_t p = leaves[l].patchIndex;
    const uint64_t keys[2] = {lineKey(p, alongU ? r.y : r.x), lineKey(p, alongU ? r.w : r.z)};
    leafLines[l] = {number(keys[0]), number(keys[1])};
    lastKeys[0] = keys[0], lastKeys[1] = keys[1];
    last = leafLines[l];
  }
  return leafLines;
}

// Each line's room in the index's array (two points per leaf edge on it), then the leaf
// corners on the lines: u along the lines v = const, v along u = const.
void fillLines(const std::vector<QuadLeaf>& leaves, bool alongU,
               const std::vector<LeafLines>& leafLines, LineIndex& index) {
  std::vector<uint32_t> room(index.size());
  for (const LeafLines& ll : leafLines) room[ll[0]] += 2, room[ll[1]] += 2;
  index.allocatePoints(room);
  for (size_t l = 0; l < leaves.size(); ++l) {
    const gpu::vec4& r = leaves[l].rect;
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        if (alongU)
          index.addOrFold(leafLines[l][j], {i ? r.z : r.x, r.z - r.x});
        else
          index.addOrFold(leafLines[l][i], {j ? r.w : r.y, r.w - r.y});
      }
  }
}

// Appends a point to a shared side's points, folded into the last one as LineIndex::addOrFold
// does: the next leaf along the side most often repeats the corner it shares with the last.
void addOrFold(std::vector<LinePoint>& points, const LinePoint& point) {
  if (points.empty() || !foldedInto(points.back(), point)) points.push_back(point);
}

// The leaf edges on a side of their patch, in leaf order, as visit(patch, side, t0, t1): the
// edge's ends at t0 < t1 along the side. A leaf's sides come in the order in which the
// corner-by-corner walk this replaced met their last corners (v = 0, u = 0, v = 1, u = 1), so
// that a group's side (LinePoints::groupSide, the last one met) stays that walk's.
template <typename Visit>
void forEachSideEdge(const std::vector<QuadLeaf>& leaves, Visit&& visit) {
  for (const QuadLeaf& leaf : leaves) {
    const gpu::vec4& r = leaf.rect;
    const uint32_t p = leaf.patchIndex;
    if (r.y == 0.0f) visit(p, kSideV0, r.x, r.z);
    if (r.x == 0.0f) visit(p, kSideU0, r.y, r.w);
    if (r.w == 1.0f) visit(p, kSideV1, r.x, r.z);
    if (r.z == 1.0f) visit(p, kSideU1, r.y, r.w);
  }
}

// The leaf corners on the patches' sides: shared sides' points in canonical parameters, folded
// sides' corners (their order free: FoldedSide::corners is sorted before use).
void collectSidePoints(const std::vector<QuadLeaf>& leaves, SeamVertices& seams,
                       LinePoints& lines) {
  const PatchTopology& topology = seams.topology();
  // Each group's room first (two points an edge, before folding): grown point by point, the
  // groups' arrays took ~5 reallocations each.
  std::vector<uint32_t> room(lines.shared.size(), 0);
  forEachSideEdge(leaves, [&](uint32_t p, int side, float, float) {
    if (const int32_t g = topology.sides[p][side].group; g >= 0) room[size_t(g)] += 2;
  });
  for (size_t g = 0; g < room.size(); ++g) lines.shared[g].reserve(room[g]);
  forEachSideEdge(leaves, [&](uint32_t p, int side, float t0, float t1) {
    const SideInfo& s = topology.sides[p][side];
    if (s.group >= 0) {
      std::vector<LinePoint>& points = lines.shared[size_t(s.group)];
      addOrFold(points, {canonical(s, t0), t1 - t0});
      addOrFold(points, {canonical(s, t1), t1 - t0});
      lines.groupSide[size_t(s.group)] = {p, side};
    }
    if (const int32_t f = seams.foldOf(p, side); f >= 0) {
      std::vector<float>& corners = seams.fold(uint32_t(f)).corners;
      corners.push_back(t0);
      corners.push_back(t1);
    }
  });
}

}  // namespace

LinePoints collectLinePoints(const std::vector<QuadLeaf>& leaves, SeamVertices& seams,
                             unsigned threads,
                             const std::function<void(LinePoints&, LineSet)>& filled) {
  const PatchTopology& topology = seams.topology();
  // A line has ~5 (coarse trees) to ~18 (fine ones) leaves along it: a table sized by the
  // leaves would be mostly empty, megabytes faulted in at every call; it grows when needed.
  const size_t expectedLines = leaves.size() / 16 + 16;
  LinePoints lines{LineIndex(expectedLines), LineIndex(expectedLines), {}, {}, {}, {}};
  lines.shared.resize(topology.groupCount);
  lines.groupSide.assign(topology.groupCount, {0, -1});
  // The shared sides' hook follows each direction's once the sides' points are in (collected
  // first, on the u thread): both threads share that work as they come free, and end about
  // together on 2 cores. Nobody waits for the sides: a thread that would have to skips.
  std::atomic<bool> sidesCollected{false};
  // The two directions' lines are independent: each numbered and filled on a thread of its
  // own (the sides' points with the lines along u).
  parallelFor(2, threads, [&](size_t begin, size_t end) {
    for (size_t part = begin; part < end; ++part) {
      const bool alongU = part == 0;
      if (alongU) {
        collectSidePoints(leaves, seams, lines);
        sidesCollected.store(true, std::memory_order_release);
      }
      LineIndex& index = alongU ? lines.alongU : lines.alongV;
      std::vector<LeafLines>& leafLines = alongU ? lines.leafLinesU : lines.leafLinesV;
      leafLines = numberLeafLines(leaves, alongU, index);
      fillLines(leaves, alongU, leafLines, index);
      if (!filled) continue;
      filled(lines, alongU ? LineSet::kAlongU : LineSet::kAlongV);
      if (sidesCollected.load(std::memory_order_acquire)) filled(lines, LineSet::kSharedSides);
    }
  });
  return lines;
}

}  // namespace tessera::triangulate_detail
