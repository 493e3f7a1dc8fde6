// collectLinePoints (detail/line_points.h): puts each leaf corner on its lines, before near
// points are merged and the leaves walked. The leaves' lines are numbered first, so that each
// line's room in LineIndex's one array is known before it is filled.
#include "mesh/detail/line_points.h"

namespace tessera::triangulate_detail {
namespace {

// Numbers every leaf's lines, each looked up once, in the order its corners meet them (the
// lines' numbers follow it; a line's points are sorted before use, their order free).
std::vector<LeafLines> numberLeafLines(const std::vector<QuadLeaf>& leaves, LinePoints& lines) {
  std::vector<LeafLines> leafLines(leaves.size());
  for (size_t l = 0; l < leaves.size(); ++l) {
    const gpu::vec4& r = leaves[l].rect;
    const uint32_t p = leaves[l].patchIndex;
    leafLines[l] = {lines.alongU.number(lineKey(p, r.y)), lines.alongU.number(lineKey(p, r.w)),
                    lines.alongV.number(lineKey(p, r.x)), lines.alongV.number(lineKey(p, r.z))};
  }
  return leafLines;
}

// Each line's room in the index's array: two points per leaf edge on it.
void allocatePoints(const std::vector<LeafLines>& leafLines, LinePoints& lines) {
  std::vector<uint32_t> alongU(lines.alongU.size()), alongV(lines.alongV.size());
  for (const LeafLines& ll : leafLines) {
    alongU[ll[0]] += 2, alongU[ll[1]] += 2;
    alongV[ll[2]] += 2, alongV[ll[3]] += 2;
  }
  lines.alongU.allocatePoints(alongU);
  lines.alongV.allocatePoints(alongV);
}

}  // namespace

LinePoints collectLinePoints(const std::vector<QuadLeaf>& leaves, SeamVertices& seams) {
  const PatchTopology& topology = seams.topology();
  LinePoints lines{LineIndex(leaves.size() / 4), LineIndex(leaves.size() / 4), {}, {}, {}};
  lines.shared.resize(topology.groupCount);
  lines.groupSide.assign(topology.groupCount, {0, -1});
  lines.leafLines = numberLeafLines(leaves, lines);
  const std::vector<LeafLines>& leafLines = lines.leafLines;
  allocatePoints(leafLines, lines);
  for (size_t l = 0; l < leaves.size(); ++l) {
    const gpu::vec4& r = leaves[l].rect;
    const uint32_t p = leaves[l].patchIndex;
    const LeafLines& ll = leafLines[l];
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const float u = i ? r.z : r.x, v = j ? r.w : r.y;
        lines.alongU.add(ll[j], {u, r.z - r.x});
        lines.alongV.add(ll[2 + i], {v, r.w - r.y});
        // The sides (u, v) is on: none, one, or two at a corner of the parameter square.
        for (int side : {kSideV0, kSideV1, kSideU0, kSideU1}) {
          const bool alongU = side == kSideV0 || side == kSideV1;
          const float t = alongU ? u : v, fixed = alongU ? v : u;
          if (fixed != (side == kSideV0 || side == kSideU0 ? 0.0f : 1.0f)) continue;
          const SideInfo& s = topology.sides[p][side];
          if (s.group >= 0) {
            lines.shared[s.group].push_back({canonical(s, t), alongU ? r.z - r.x : r.w - r.y});
            lines.groupSide[s.group] = {p, side};
          }
          const int32_t f = seams.foldOf(p, side);
          if (f >= 0) seams.fold(uint32_t(f)).corners.push_back(t);
        }
      }
  }
  return lines;
}

}  // namespace tessera::triangulate_detail
