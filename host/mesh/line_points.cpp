// collectLinePoints (detail/line_points.h): one pass over the leaves that puts each corner on
// its lines, before near points are merged and the leaves walked.
#include "mesh/detail/line_points.h"

namespace tessera::triangulate_detail {

LinePoints collectLinePoints(const std::vector<QuadLeaf>& leaves, SeamVertices& seams) {
  const PatchTopology& topology = seams.topology();
  LinePoints lines{LineIndex(leaves.size() / 4), LineIndex(leaves.size() / 4), {}, {}};
  lines.shared.resize(topology.groupCount);
  lines.groupSide.assign(topology.groupCount, {0, -1});
  for (const QuadLeaf& leaf : leaves) {
    const gpu::vec4& r = leaf.rect;
    const uint32_t p = leaf.patchIndex;
    // The leaf's four lines, each looked up once, in the order its corners meet them (the
    // lines' numbers follow it; a line's points are sorted before use, their order free).
    const uint32_t lineV[2] = {lines.alongU.number(lineKey(p, r.y)),
                               lines.alongU.number(lineKey(p, r.w))};
    const uint32_t lineU[2] = {lines.alongV.number(lineKey(p, r.x)),
                               lines.alongV.number(lineKey(p, r.z))};
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const float u = i ? r.z : r.x, v = j ? r.w : r.y;
        lines.alongU.points(lineV[j]).push_back({u, r.z - r.x});
        lines.alongV.points(lineU[i]).push_back({v, r.w - r.y});
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
