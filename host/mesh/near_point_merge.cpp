// findLinePairs and mergeNearPoints (detail/near_point_merge.h): finds the near pairs of every
// line, merges them in an order that keeps meshes' bytes (LineIndex::unorderedMapOrder), and
// prunes the lines to the points that stay, noting where merged corners went.
#include "mesh/detail/near_point_merge.h"

#include <algorithm>

#include "geometry/bezier.h"
#include "mesh/near_points.h"

namespace tessera::triangulate_detail {
namespace {

// Whether the line v = fixed (alongU) or u = fixed of `patch` is one of its sides that is
// shared, collapsed or folded: their points are merged (or placed) by the side's own rules.
bool lineIsSide(const SeamVertices& seams, uint32_t patch, bool alongU, float fixed) {
  if (fixed != 0.0f && fixed != 1.0f) return false;
  const int side = alongU ? (fixed == 0.0f ? kSideV0 : kSideV1) : (fixed == 0.0f ? kSideU0 : kSideU1);
  const SideInfo& s = seams.topology().sides[patch][side];
  return s.group >= 0 || s.collapsed || seams.foldOf(patch, side) >= 0;
}

glm::dvec3 pointOf(const SeamVertices& seams, uint32_t patch, glm::vec2 uv) {
  return patchPoint(seams.patches()[patch], uv.x, uv.y);
}

// Whether fp32 positions tell two points of a patch apart (near_points.h): farther apart
// on the model, in double, than kDistinctUlps units in the last place of their coordinates.
bool distinctOnModel(const glm::dvec3& pa, const glm::dvec3& pb) {
  const glm::dvec3 m = glm::max(glm::abs(pa), glm::abs(pb));
  return glm::length(pa - pb) > kDistinctUlps * 0x1p-23 * std::max({m.x, m.y, m.z});
}

// nearPairs asks about adjacent pairs in turn, so a pair's first point is mostly the last
// pair's second: kept, each point is evaluated once, not twice (the same t bits, the same
// point).
class LastPoint {
 public:
  template <class Evaluate>
  glm::dvec3 at(float t, const Evaluate& evaluate) {
    if (!held_ || bits(t) != tBits_) {
      point_ = evaluate();
      tBits_ = bits(t);
      held_ = true;
    }
    return point_;
  }

 private:
  bool held_ = false;
  uint32_t tBits_ = 0;
  glm::dvec3 point_{0.0};
};

class NearPointMerger {
 public:
  NearPointMerger(LinePoints& lines, SeamVertices& seams, const LinePairs& pairsU,
                  const LinePairs& pairsV, const LinePairs& pairsShared, size_t leafCount)
      : lines_(lines),
        seams_(seams),
        topology_(seams.topology()),
        pairsU_(pairsU),
        pairsV_(pairsV),
        pairsShared_(pairsShared),
        leafCount_(leafCount) {}

  NearPointMerges run() {
    mergeNearPoints();
    listRepresentatives();
    return std::move(out_);
  }

 private:
  // Near-coincident points from the two sides of each line become one vertex (out_.merged):
  // the lines' pairs (findLinePairs) merged in the walk order (LineIndex), then the shared
  // sides' (SharedSidePairs) in group order.
  void mergeNearPoints() {
    for (LineIndex* line : {&lines_.alongU, &lines_.alongV}) {
      const bool alongU = line == &lines_.alongU;
      const LinePairs& pairs = alongU ? pairsU_ : pairsV_;
      const bool any = std::any_of(pairs.begin(), pairs.end(), [](const auto& p) { return !p.empty(); });
      if (!any) continue;
      for (uint32_t l : line->unorderedMapOrder(kLineIndexReserve * leafCount_)) {
        const uint32_t patch = uint32_t(line->key(l) >> 32);
        const float fixed = fromBits(uint32_t(line->key(l)));
        for (const auto& [a, b] : pairs[l])
          merge(lineKeyOf(patch, alongU, fixed, a), lineKeyOf(patch, alongU, fixed, b));
      }
    }
    for (uint32_t g = 0; g < pairsShared_.size(); ++g)
      for (const auto& [a, b] : pairsShared_[g]) merge(groupKey(g, a), groupKey(g, b));
    // Every key straight to its representative: a key set before another is met through it
    // gives the same end, so the table's order does not matter.
    for (auto it = out_.merged.begin(); it != out_.merged.end(); ++it)
      it.value() = out_.find(it->first);
  }

  // The line indices keep the points that stay, as the vertices they are: a point merged into
  // another is that one's vertex, and a ring over both would meet it twice. A leaf edge that
  // ends at a merged point ends where that point's vertex is on the line (MovedCorners).
  void listRepresentatives() {
    if (out_.merged.empty()) return;
    // Which points can be merged ones, so that only they are looked up: a point (u, v) of a
    // patch is keyed by (patch, u, v) unless u or v is 0 or 1 (seam_vertices.h), so a merged
    // (patch, u, v) key is on the lines v and u of its patch alone, and any other merged key
    // is on a side's line or at a line's end. A point that is no merged key stays.
    std::vector<uint8_t> listsMergedU(lines_.alongU.size()), listsMergedV(lines_.alongV.size());
    // Any other merged key is a shared side's point (by its group) or a position (a patch
    // corner, or a collapsed or folded side's point); a fold's own points are never merged.
    std::vector<uint8_t> groupMerged(lines_.shared.size());
    bool positionMerged = false;
    for (const auto& [key, target] : out_.merged) {
      if (key.kind == kEdgeParam) groupMerged[key.a] = 1;
      if (key.kind == kPosition) positionMerged = true;
      if (key.kind != kPatchParam) continue;
      const float u = fromBits(uint32_t(key.b >> 32)), v = fromBits(uint32_t(key.b));
      if (const uint32_t l = lines_.alongU.find(lineKey(key.a, v)); l != UINT32_MAX) listsMergedU[l] = 1;
      if (const uint32_t l = lines_.alongV.find(lineKey(key.a, u)); l != UINT32_MAX) listsMergedV[l] = 1;
    }
    // Whether a point inside a side can be a merged key that is no (patch, u, v) one (those
    // are listed above): only on a side whose group has a merged point, or on a collapsed or
    // folded side once a position is merged. A line's ends are on sides: most lines need no
    // look-up at all (a few merges on the shared sides had every line's ends looked up).
    const auto sideMayHoldMerged = [&](uint32_t patch, int side) {
      const SideInfo& s = topology_.sides[patch][side];
      if (s.group >= 0) return groupMerged[size_t(s.group)] != 0;
      return positionMerged && (s.collapsed || seams_.foldOf(patch, side) >= 0);
    };
    for (LineIndex* line : {&lines_.alongU, &lines_.alongV}) {
      const bool alongU = line == &lines_.alongU;
      const std::vector<uint8_t>& listsMerged = alongU ? listsMergedU : listsMergedV;
      // The sides a line's ends are on (t = 0, t = 1), and the side a line at 0 or 1 is.
      const int startSide = alongU ? kSideU0 : kSideV0, endSide = alongU ? kSideU1 : kSideV1;
      const int sideAt0 = alongU ? kSideV0 : kSideU0, sideAt1 = alongU ? kSideV1 : kSideU1;
      std::vector<uint32_t>& movedOf = alongU ? out_.movedOfU : out_.movedOfV;
      movedOf.assign(line->size(), 0);
      // In the lines' own order: merging is done, so the position ids handed out here
      // (patch corners no merge met) only tell positions apart, and each line's moved
      // corners are its own.
      for (uint32_t l = 0; l < line->size(); ++l) {
        const uint64_t key = line->key(l);
        const uint32_t patch = uint32_t(key >> 32);
        const float fixed = fromBits(uint32_t(key));
        // A side's own line ends at patch corners.
        const bool mayHoldMerged =
            listsMerged[l] ||
            (fixed == 0.0f || fixed == 1.0f
                 ? positionMerged || sideMayHoldMerged(patch, fixed == 0.0f ? sideAt0 : sideAt1)
                 : sideMayHoldMerged(patch, startSide) || sideMayHoldMerged(patch, endSide));
        if (!mayHoldMerged) continue;
        const LinePointRange points = line->points(l);
        // Else only its ends at t = 0 and 1 (sorted by findLinePairs: the first and last).
        const bool everyPoint = listsMerged[l] || fixed == 0.0f || fixed == 1.0f;
        size_t kept = 0;
        for (size_t k = 0; k < points.size(); ++k) {
          const LinePoint point = points[k];
          if (!everyPoint && point.t != 0.0f && point.t != 1.0f) {
            // Up to the points at t = 1, all stay.
            size_t until = points.size();
            while (until > k + 1 && points[until - 1].t == 1.0f) --until;
            if (kept != k) std::copy(&points[k], &points[0] + until, &points[kept]);
            kept += until - k;
            k = until - 1;
            continue;
          }
          const VertexKey own = lineKeyOf(patch, alongU, fixed, point.t);
          const VertexKey r = out_.find(own);
          if (r == own) {
            points[kept++] = point;
            continue;
          }
          // Where r is on this line, if it is (merged along another line, it is not).
          float t = point.t;
          if (r.kind == kPatchParam && r.a == patch) {
            const float u = fromBits(uint32_t(r.b >> 32)), v = fromBits(uint32_t(r.b));
            if (alongU && v == fixed) t = u;
            if (!alongU && u == fixed) t = v;
          }
          if (movedOf[l] == 0) {
            out_.moved.emplace_back();
            movedOf[l] = uint32_t(out_.moved.size());
          }
          out_.moved[movedOf[l] - 1].emplace_back(point.t, t);
        }
        line->shrink(l, kept);
      }
    }
    out_.sharedMoved.resize(lines_.shared.size());
    for (uint32_t g = 0; g < lines_.shared.size(); ++g) {
      // A point inside the side is keyed by its group, one at an end by a patch corner.
      if (!groupMerged[g] && !positionMerged) continue;
      std::vector<LinePoint>& points = lines_.shared[g];
      size_t kept = 0;
      for (const LinePoint& point : points) {
        if (!groupMerged[g] && point.t != 0.0f && point.t != 1.0f) {
          points[kept++] = point;
          continue;
        }
        const VertexKey own = groupKey(g, point.t);
        const VertexKey r = out_.find(own);
        if (r == own) {
          points[kept++] = point;
          continue;
        }
        float c = point.t;
        if (r.kind == kEdgeParam && r.a == g) c = fromBits(uint32_t(r.b));
        for (float end : {0.0f, 1.0f})
          if (r == groupKey(g, end)) c = end;
        out_.sharedMoved[g].emplace_back(point.t, c);
      }
      points.resize(kept);
    }
  }

  // The vertex key of canonical parameter c on shared group g: its ends are patch corners.
  // (Only there is c turned back into a patch parameter: 1 − c is exact at 0 and 1 alone.)
  VertexKey groupKey(uint32_t g, float c) {
    if (c != 0.0f && c != 1.0f) return {kEdgeParam, g, bits(c)};
    const auto [patch, side] = lines_.groupSide[g];
    const SideInfo& s = topology_.sides[patch][side];
    const float t = s.reversed ? 1.0f - c : c;
    const bool alongU = side == kSideV0 || side == kSideV1;
    const float fixed = side == kSideV0 || side == kSideU0 ? 0.0f : 1.0f;
    return alongU ? seams_.baseKey(patch, t, fixed) : seams_.baseKey(patch, fixed, t);
  }

  VertexKey lineKeyOf(uint32_t patch, bool alongU, float fixed, float t) {
    return alongU ? seams_.baseKey(patch, t, fixed) : seams_.baseKey(patch, fixed, t);
  }

  // Merging keeps, of two keys, the one ranked first: a patch corner, then a point of a shared
  // side, then a point inside a patch; then the smaller parameter (on a shared side, the
  // canonical one: the first of a run, as both sides see it).
  static bool ranksBefore(const VertexKey& x, const VertexKey& y) {
    static constexpr int rank[] = {3, 2, 0, 1};  // by KeyKind
    if (rank[x.kind] != rank[y.kind]) return rank[x.kind] < rank[y.kind];
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  }

  void merge(const VertexKey& x, const VertexKey& y) {
    if (x.kind == kFoldPosition || y.kind == kFoldPosition) return;  // placed by the fold
    VertexKey rx = out_.find(x), ry = out_.find(y);
    if (rx == ry) return;
    if (ranksBefore(ry, rx)) std::swap(rx, ry);
    out_.merged[ry] = rx;
  }

  LinePoints& lines_;
  SeamVertices& seams_;
  const PatchTopology& topology_;
  const LinePairs& pairsU_;
  const LinePairs& pairsV_;
  const LinePairs& pairsShared_;
  const size_t leafCount_;
  NearPointMerges out_;
};

}  // namespace

LinePairs findLinePairs(LineIndex& lines, const SeamVertices& seams, bool alongU) {
  LinePairs pairs(lines.size());
  for (size_t l = 0; l < lines.size(); ++l) {
    const uint32_t patch = uint32_t(lines.key(l) >> 32);
    const float fixed = fromBits(uint32_t(lines.key(l)));
    const auto uvOf = [&](float t) { return alongU ? glm::vec2(t, fixed) : glm::vec2(fixed, t); };
    // A side's points are merged by the side's own rules: its pairs are dropped, so nothing
    // on it needs evaluating (its points are still sorted and folded).
    const bool side = lineIsSide(seams, patch, alongU, fixed);
    LastPoint last;
    const auto distinct = [&](float a, float b) {
      if (side) return true;
      const auto at = [&](float t) { return last.at(t, [&] { return pointOf(seams, patch, uvOf(t)); }); };
      const glm::dvec3 pa = at(a);
      return distinctOnModel(pa, at(b));
    };
    size_t count = lines.points(l).size();
    pairs[l] = nearPairs(lines.points(l).begin(), count, distinct);
    lines.shrink(l, count);
    if (side) pairs[l].clear();
  }
  return pairs;
}

void SharedSidePairs::findUntaken(LinePoints& lines, const SeamVertices& seams) {
  const PatchTopology& topology = seams.topology();
  for (size_t g; (g = next_.fetch_add(1, std::memory_order_relaxed)) < pairs_.size();) {
    const auto [patch, side] = lines.groupSide[g];
    if (side < 0) continue;  // no leaf of this triangulation is on it (a streamed group's scope)
    const SideInfo& s = topology.sides[patch][side];
    const bool alongU = side == kSideV0 || side == kSideV1;
    const float fixed = side == kSideV0 || side == kSideU0 ? 0.0f : 1.0f;
    // (1 − c need not give back the leaf's own t bit for bit; a distance does not mind.)
    const auto uvOf = [&](float c) {
      const float t = canonical(s, c);
      return alongU ? glm::vec2(t, fixed) : glm::vec2(fixed, t);
    };
    LastPoint last;
    const auto distinct = [&, patch = patch](float a, float b) {
      const auto at = [&](float c) {
        return last.at(c, [&] { return pointOf(seams, patch, uvOf(c)); });
      };
      const glm::dvec3 pa = at(a);
      return distinctOnModel(pa, at(b));
    };
    pairs_[g] = nearPairs(lines.shared[g], distinct);
  }
}

NearPointMerges mergeNearPoints(LinePoints& lines, SeamVertices& seams, const LinePairs& pairsU,
                                const LinePairs& pairsV, const LinePairs& pairsShared,
                                size_t leafCount) {
  return NearPointMerger(lines, seams, pairsU, pairsV, pairsShared, leafCount).run();
}

}  // namespace tessera::triangulate_detail
