// The leaf walk (detail/leaf_walk.h): one leaf's ring — its corners, the corners of finer
// neighbours and the shared, folded or merged points on its edges — and its triangles: two
// for a plain leaf, n − 2 without a new vertex for a rule-T leaf (ring_triangulation.h), else
// the fan from its split point (docs/watertight.md). The hot loop of the triangulator: every
// helper it calls per leaf is in this file or inline in the detail headers.
#include "mesh/detail/leaf_walk.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

#include "common/hash_map.h"
#include "mesh/detail/run_places.h"
#include "mesh/ring_triangulation.h"

namespace tessera::triangulate_detail {
namespace {

// Where on its line the vertex of the corner at t lies.
float movedTo(const MovedCorners& moved, float t) {
  if (moved.empty()) return t;
  auto it = std::lower_bound(moved.begin(), moved.end(), std::pair<float, float>(t, -INFINITY));
  return it != moved.end() && it->first == t ? it->second : t;
}

// Positions strictly between lo and hi (lo < hi), ascending.
template <typename Points>
void between(const Points& points, float lo, float hi, std::vector<float>& out) {
  out.clear();
  // One search: a leaf edge has few points inside, most often none.
  auto first = std::upper_bound(points.begin(), points.end(), lo,
                                [](float t, const LinePoint& p) { return t < p.t; });
  for (; first != points.end() && first->t < hi; ++first) out.push_back(first->t);
}

class LeafWalker {
 public:
  explicit LeafWalker(const LeafWalkTables& tables)
      : seams_(tables.seams),
        topology_(tables.seams.topology()),
        lines_(tables.lines),
        merges_(tables.merges),
        mergeTargets_(tables.mergeTargets) {}

  void walk(const std::vector<QuadLeaf>& leaves, size_t begin, size_t end, uint32_t firstPatch,
            uint32_t endPatch, LeafRun& run) {
    // One table per thread, kept (RunPlaces::reset). About one distinct vertex per leaf in a
    // run, a few more on its border.
    static thread_local RunPlaces places(0);
    places.reset(3 * (end - begin) / 2);
    LeafWork work{places};
    work.out = &run;
    for (size_t l = begin; l < end; ++l) {
      const QuadLeaf& leaf = leaves[l];
      work.silent = leaf.patchIndex < firstPatch || leaf.patchIndex >= endPatch;
      triangulateLeaf(leaf, lines_.leafLinesU[l], lines_.leafLinesV[l], work);
    }
    // A merge target is also asked for by the leaves around the points merged into it.
    const bool anyTargets = !mergeTargets_.empty();
    for (uint32_t k = 0; k < run.vertices.size(); ++k)
      if (run.vertices[k].cover != kAllAround ||
          (anyTargets && mergeTargets_.count(run.vertices[k].key) != 0))
        run.border.push_back(k);
  }

 private:
  struct RingVertex {
    uint32_t vertex;  // in LeafRun::vertices: one key, one place (numbered once: triangulate.cpp)
    glm::vec2 uv;     // on the leaf's own patch
    bool operator==(const RingVertex& o) const { return vertex == o.vertex; }
  };

  // How much of the neighbourhood of a vertex's point the run's leaves cover, in quarters:
  // a leaf asks for a point as its corner (1), inside its edge (2) or inside itself (4, the
  // fan's centre). The leaves of a patch tile it, so 4 quarters are all the leaves that touch
  // the point. kElsewhere: the key is not the point's own (a patch corner, a shared or folded
  // side's point, a merged one), so leaves away from the point may ask for it too.
  static constexpr uint32_t kCorner = 1, kEdge = 2, kInside = 4, kAllAround = 4,
                            kElsewhere = 0x100;

  enum Edge { kBottom, kRight, kTop, kLeft };  // a leaf's edges in ring order

  // Where the last leaves' searches on their edges' lines ended. The leaves come in rows of
  // small blocks: the next leaf in a row starts its bottom and top edges one point past where
  // the last one's ended, and its left edge is the last leaf's right one; a leaf above one of
  // the last few starts its bottom edge where that one's top edge started, and its left and
  // right edges one point past where that one's ended. A guess is taken only where it is
  // std::upper_bound's answer (the points before it at most t, it past t), so it is the
  // search's result exactly; else the search.
  struct LineHints {
    static constexpr int kBelow = 4;  // the last leaves looked at for the one below
    const LinePoint* next[2] = {};  // bottom, top: one past the last search's end
    const LinePoint* rightFirst = nullptr;      // this leaf's right edge's search
    const LinePoint* lastRightFirst = nullptr;  // the last leaf's
    // Of the last kBelow leaves: the top edges' starts, the right and left edges' ends + 1.
    const LinePoint* below[3][kBelow] = {};
    unsigned slot[3] = {};  // kBelow a power of two: the wrap is a mask

    static bool fits(const PointRange<const LinePoint>& points, const LinePoint* h, float t) {
      return h && std::less_equal<>()(points.begin(), h) && std::less_equal<>()(h, points.end()) &&
             (h == points.begin() || h[-1].t <= t) && (h == points.end() || h->t > t);
    }

    const LinePoint* upperBound(int edge, const PointRange<const LinePoint>& points, float t) const {
      const LinePoint* h = edge == kBottom ? next[0]
                           : edge == kTop  ? next[1]
                           : edge == kLeft ? lastRightFirst
                                           : nullptr;
      if (fits(points, h, t)) return h;
      if (edge != kTop) {
        const int list = edge == kBottom ? 0 : edge == kRight ? 1 : 2;
        for (const LinePoint* g : below[list])
          if (fits(points, g, t)) return g;
      }
      return std::upper_bound(points.begin(), points.end(), t,
                              [](float x, const LinePoint& p) { return x < p.t; });
    }

    void remember(int edge, const PointRange<const LinePoint>& points, const LinePoint* first,
                  const LinePoint* last) {
      const LinePoint* past = last != points.end() ? last + 1 : nullptr;
      if (edge == kRight) lastRightFirst = rightFirst, rightFirst = first;
      if (edge == kBottom || edge == kTop) next[edge == kTop] = past;
      if (edge == kBottom) return;
      const int list = edge == kTop ? 0 : edge == kRight ? 1 : 2;
      below[list][slot[list]] = edge == kTop ? first : past;
      slot[list] = (slot[list] + 1) % kBelow;
    }
  };

  // One thread's walk: where it writes, and the leaf being triangulated.
  struct LeafWork {
    LineHints lineHints;
    LeafRun* out = nullptr;
    explicit LeafWork(RunPlaces& places) : place(places) {}
    RunPlaces& place;  // key → its place in out->vertices
    bool silent = false;        // the leaf is outside the scope
    bool touchesFold = false;   // it has a vertex on a folded side
    bool touchesMerge = false;  // ... or a vertex merged into a near one
    std::vector<RingVertex> ring;
    std::vector<glm::vec2> ringUv;
    std::vector<uint32_t> ringVertices;
    std::vector<std::array<uint32_t, 3>> ringTriangles;
    std::vector<float> scratch;
  };

  // ring.push_back by const reference: its small body is inlined, where the rvalue overload
  // (emplace_back) stayed an out-of-line call, ~5% of the walk's instructions.
  static void append(std::vector<RingVertex>& ring, const RingVertex& vertex) {
    ring.push_back(vertex);
  }

  // `cover`: the quarters around the vertex's point that the leaf covers (kCorner …).
  static RingVertex query(LeafWork& work, const VertexKey& key, uint32_t patch, glm::vec2 uv,
                          uint32_t cover) {
    std::vector<VertexQuery>& vertices = work.out->vertices;
    bool added;
    const uint32_t place = work.place.findOrAdd(key, uint32_t(vertices.size()), added);
    if (added) {
      vertices.push_back({key, patch, uv, 0});
    }
    vertices[place].cover += key.kind == kPatchParam ? cover : kElsewhere;
    return {place, uv};
  }

  // The key of a point strictly inside its patch: baseKey's, without looking for a side.
  static VertexKey innerKey(uint32_t patch, float u, float v) {
    return {kPatchParam, patch, (uint64_t(bits(u)) << 32) | bits(v)};
  }

  // The vertex at (u, v) of `patch`, welded with every other patch's vertex at that point and
  // with the near points merged into it. `inner`: (u, v) is strictly inside the patch.
  // `mayMerge`: it may have been merged into a near point (false for a leaf corner on a line
  // none of whose points was: NearPointMerges::movedOn).
  // vertexAt and edgeInterior are inlined into triangulateLeaf (four calls each a leaf): their
  // calls' entries and exits were ~12% of the walk's instructions.
  [[gnu::always_inline]] RingVertex vertexAt(LeafWork& work, uint32_t patch, float u, float v,
                                             uint32_t cover, bool inner, bool mayMerge) {
    int side;
    float t;
    if (!inner && onSide(u, v, side, t) && seams_.foldOf(patch, side) >= 0) work.touchesFold = true;
    const VertexKey base = inner ? innerKey(patch, u, v) : seams_.baseKey(patch, u, v);
    const VertexKey key = mayMerge ? merges_.resolve(base, work.touchesMerge) : base;
    return query(work, key, patch, glm::vec2(u, v), key == base ? cover : kElsewhere);
  }

  // Appends the vertices strictly inside the leaf edge from t0 to t1 (in ring order) on the
  // line `fixed` (v = fixed when alongU, else u = fixed), number `line` in its LineIndex.
  // `inner`: the leaf is strictly inside its patch (so is every point of its edges' lines
  // between its corners).
  // `moved`: the line's corners merged away (NearPointMerges::movedOn), looked up once a leaf.
  [[gnu::always_inline]] void edgeInterior(LeafWork& work, uint32_t patch, int edge, float fixed,
                                           uint32_t line, const MovedCorners* moved, float t0,
                                           float t1, bool inner) {
    const bool alongU = edge == kBottom || edge == kTop;
    std::vector<RingVertex>& ring = work.ring;
    std::vector<float>& scratch = work.scratch;
    int side = -1;
    if (!inner && alongU && (fixed == 0.0f || fixed == 1.0f)) side = fixed == 0.0f ? kSideV0 : kSideV1;
    if (!inner && !alongU && (fixed == 0.0f || fixed == 1.0f)) side = fixed == 0.0f ? kSideU0 : kSideU1;
    if (side >= 0) {
      const SideInfo& s = topology_.sides[patch][side];
      if (s.collapsed) return;  // every point of it is the same vertex
      if (s.group >= 0) {
        // Compare in the shared curve's own parameter, the same on both sides.
        float c0 = canonical(s, t0), c1 = canonical(s, t1);
        const std::vector<MovedCorners>& sharedMoved = merges_.sharedMoved;
        if (!sharedMoved.empty())
          c0 = movedTo(sharedMoved[s.group], c0), c1 = movedTo(sharedMoved[s.group], c1);
        between(lines_.shared[s.group], std::min(c0, c1), std::max(c0, c1), scratch);
        if (c0 > c1) std::reverse(scratch.begin(), scratch.end());
        for (float c : scratch) {
          float t = s.reversed ? 1.0f - c : c;
          glm::vec2 uv = alongU ? glm::vec2(t, fixed) : glm::vec2(fixed, t);
          // A listed point is a vertex of its own: no merge to look up.
          append(ring, query(work, {kEdgeParam, uint32_t(s.group), bits(c)}, patch, uv, kElsewhere));
        }
        return;
      }
      if (const int32_t f = seams_.foldOf(patch, side); f >= 0) {
        work.touchesFold = true;
        const std::map<float, VertexKey>& points = seams_.fold(uint32_t(f)).points;
        auto first = points.upper_bound(std::min(t0, t1));
        auto last = points.lower_bound(std::max(t0, t1));
        std::vector<std::pair<float, VertexKey>> inside(first, last);
        if (t0 > t1) std::reverse(inside.begin(), inside.end());
        for (const auto& [t, key] : inside) {
          glm::vec2 uv = alongU ? glm::vec2(t, fixed) : glm::vec2(fixed, t);
          append(ring, query(work, key, patch, uv, kElsewhere));
        }
        return;
      }
    }
    const LineIndex& lines = alongU ? lines_.alongU : lines_.alongV;
    const PointRange<const LinePoint> points = lines.points(line);
    // The edge, before moving: a leaf's bottom and right edges run up their lines, its top and
    // left ones down (r.x < r.z, r.y < r.w), so its ends' order is known without comparing.
    bool rising = edge == kBottom || edge == kRight;
    const float lo = rising ? t0 : t1, hi = rising ? t1 : t0;
    float from = lo, to = hi;  // the ends after moving, ascending
    if (moved) {
      t0 = movedTo(*moved, t0), t1 = movedTo(*moved, t1);
      rising = t0 <= t1;
      from = std::min(t0, t1), to = std::max(t0, t1);
    }
    // The points strictly between the (moved) ends, in ring order. A listed point is a vertex
    // of its own: no merge to look up.
    const LinePoint* first = work.lineHints.upperBound(edge, points, from);
    const LinePoint* last = first;
    while (last != points.end() && last->t < to) ++last;
    work.lineHints.remember(edge, points, first, last);
    const auto place = [&](float t) {
      const glm::vec2 uv = alongU ? glm::vec2(t, fixed) : glm::vec2(fixed, t);
      const VertexKey key = inner ? innerKey(patch, uv.x, uv.y) : seams_.baseKey(patch, uv.x, uv.y);
      append(ring, query(work, key, patch, uv, t > lo && t < hi ? kEdge : kElsewhere));
    };
    if (rising)
      for (const LinePoint* p = first; p != last; ++p) place(p->t);
    else
      for (const LinePoint* p = last; p != first;) place((--p)->t);
  }

  static void emit(LeafWork& work, uint32_t patch, const RingVertex& a, const RingVertex& b,
                   const RingVertex& c) {
    if (work.silent) return;
    if (a == b || b == c || c == a) {
      ++work.out->droppedTriangles;
      return;
    }
    work.out->triangles.push_back({{a.vertex, b.vertex, c.vertex}, {a.uv, b.uv, c.uv}, patch});
  }

  // Along a fold the ring can meet one vertex twice: back to back (a, v, v, a at the fold's
  // turn) or as a spike (a, v, a, the leaf's own surface folded onto itself). A fan over them
  // would give zero-area and back-to-back triangles; the ring without them bounds the same
  // surface. Returns whether anything went.
  static bool dropFoldedBack(std::vector<RingVertex>& ring) {
    bool changed = false;
    for (bool again = true; again && ring.size() >= 2;) {
      again = false;
      const size_t n = ring.size();
      for (size_t i = 0; i < n && !again; ++i) {
        if (ring[i] == ring[(i + 1) % n]) {
          ring.erase(ring.begin() + long((i + 1) % n));
          again = true;
        } else if (n >= 3 && ring[i] == ring[(i + 2) % n]) {
          // Drop the spike's tip and its second base, keeping the first.
          const size_t tip = (i + 1) % n, base = (i + 2) % n;
          ring.erase(ring.begin() + long(std::max(tip, base)));
          ring.erase(ring.begin() + long(std::min(tip, base)));
          again = true;
        }
      }
      changed = changed || again;
    }
    return changed;
  }

  // Consecutive ring entries at one vertex (near points merged into it, near_points.h) are
  // one entry: the fan over them would only add triangles with two corners at one vertex.
  static void dropRepeats(std::vector<RingVertex>& ring) {
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    while (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
  }

  // Rule T's leaves: its bound holds for any triangle with corners in the leaf's rectangle
  // (docs/quadtree.md, "Rule T: tolerance"), so their rings need no centre vertex. Rules A–D
  // (and rule T's MaxDepth / MinSize leaves, which share their causes) keep the fan.
  static bool provenAnyTriangulation(uint32_t cause) {
    return cause == gpu::kCauseWithinTolerance || cause == gpu::kCauseCulled ||
           cause == gpu::kCauseEyePlane;
  }

  // Whether the ring is the leaf's four corners (of a rectangle of some area), four vertices.
  static bool cornerRing(const std::vector<RingVertex>& ring, const gpu::vec4& r) {
    const auto distinct = [&](size_t a, size_t b) { return !(ring[a] == ring[b]); };
    return r.x < r.z && r.y < r.w && ring[0].uv == glm::vec2(r.x, r.y) &&
           ring[1].uv == glm::vec2(r.z, r.y) && ring[2].uv == glm::vec2(r.z, r.w) &&
           ring[3].uv == glm::vec2(r.x, r.w) && distinct(0, 1) && distinct(0, 2) &&
           distinct(0, 3) && distinct(1, 2) && distinct(1, 3) && distinct(2, 3);
  }

  // How many distinct vertices the ring holds. A ring has a handful: compared pairwise, where
  // sorting a copy cost more than the comparisons.
  static size_t distinctVertices(LeafWork& work) {
    const std::vector<RingVertex>& ring = work.ring;
    const size_t n = ring.size();
    if (n > 16) {
      std::vector<uint32_t>& sorted = work.ringVertices;
      sorted.resize(n);
      for (size_t k = 0; k < n; ++k) sorted[k] = ring[k].vertex;
      std::sort(sorted.begin(), sorted.end());
      return size_t(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
    }
    size_t distinct = 0;
    for (size_t k = 0; k < n; ++k) {
      size_t j = 0;
      while (j < k && !(ring[j] == ring[k])) ++j;
      distinct += j == k;
    }
    return distinct;
  }

  // The ring as n − 2 triangles without a new vertex (ring_triangulation.h). Only where every
  // vertex is met once, or twice in a row (a collapsed side's two corners, whose triangle
  // collapses and is dropped as in the fan): otherwise the fan, whose triangles each hold one
  // ring edge, is kept.
  static bool triangulateRing(LeafWork& work, uint32_t patch, const gpu::vec4& r,
                              uint32_t diagonal) {
    const std::vector<RingVertex>& ring = work.ring;
    const size_t n = ring.size();
    if (n == 4 && cornerRing(ring, r)) {
      // What triangulateRectangleRingAlong gives four distinct corners: a triangle per half.
      if (diagonal == gpu::kToleranceAntiDiagonal) {
        emit(work, patch, ring[3], ring[1], ring[2]);
        emit(work, patch, ring[1], ring[3], ring[0]);
        return true;
      }
      if (diagonal == gpu::kToleranceMainDiagonal) {
        emit(work, patch, ring[2], ring[0], ring[1]);
        emit(work, patch, ring[0], ring[2], ring[3]);
        return true;
      }
    }
    // Only grown: resize's zero-fill of the new entries, out of line, cost ~120 instructions a
    // ring, rings' sizes going up and down.
    if (work.ringUv.size() < n) work.ringUv.resize(n);
    for (size_t k = 0; k < n; ++k) work.ringUv[k] = ring[k].uv;
    size_t repeats = ring[n - 1] == ring[0];
    for (size_t k = 0; k + 1 < n; ++k) repeats += ring[k] == ring[k + 1];
    if (distinctVertices(work) + repeats != n) return false;
    if (!triangulateRectangleRingAlong(work.ringUv.data(), n, {r.x, r.y}, {r.z, r.w}, diagonal,
                                       work.ringTriangles))
      return false;
    for (const auto& t : work.ringTriangles) emit(work, patch, ring[t[0]], ring[t[1]], ring[t[2]]);
    return true;
  }

  void triangulateLeaf(const QuadLeaf& leaf, const LeafLines& linesU, const LeafLines& linesV,
                       LeafWork& work) {
    const uint32_t p = leaf.patchIndex;
    const gpu::vec4& r = leaf.rect;
    std::vector<RingVertex>& ring = work.ring;
    ring.clear();
    work.touchesFold = work.touchesMerge = false;
    // Counter-clockwise: bottom (v0, u rising), right (u1, v rising), top (v1, u falling),
    // left (u0, v falling); each edge contributes its start corner and interior vertices.
    // Most leaves touch no side of their patch: no side, fold or patch corner to look for.
    const bool inner = r.x > 0.0f && r.z < 1.0f && r.y > 0.0f && r.w < 1.0f;
    // A corner is a point of its line along u: merged only if a point of that line was.
    const MovedCorners* const bottomMoved = merges_.movedOn(true, linesU[0]);
    const MovedCorners* const topMoved = merges_.movedOn(true, linesU[1]);
    const bool bottomMerged = bottomMoved != nullptr, topMerged = topMoved != nullptr;
    append(ring, vertexAt(work, p, r.x, r.y, kCorner, inner, bottomMerged));
    edgeInterior(work, p, kBottom, r.y, linesU[0], bottomMoved, r.x, r.z, inner);
    append(ring, vertexAt(work, p, r.z, r.y, kCorner, inner, bottomMerged));
    edgeInterior(work, p, kRight, r.z, linesV[1], merges_.movedOn(false, linesV[1]), r.y, r.w,
                 inner);
    append(ring, vertexAt(work, p, r.z, r.w, kCorner, inner, topMerged));
    edgeInterior(work, p, kTop, r.w, linesU[1], topMoved, r.z, r.x, inner);
    append(ring, vertexAt(work, p, r.x, r.w, kCorner, inner, topMerged));
    edgeInterior(work, p, kLeft, r.x, linesV[0], merges_.movedOn(false, linesV[0]), r.w, r.y,
                 inner);

    const bool folded = work.touchesFold && dropFoldedBack(ring);
    if (work.touchesMerge) dropRepeats(ring);
    if (ring.size() < 3) return;
    // Four entries are the four corners unless a merge took one: a leaf kept to a diagonal then
    // goes through triangulateRing, which finds that diagonal's corners or keeps the fan.
    const bool cornerDiagonal = leaf.diagonal == gpu::kToleranceAnyDiagonal ||
                                (leaf.diagonal == gpu::kToleranceMainDiagonal && !work.touchesMerge);
    if (ring.size() == 4 && !folded && cornerDiagonal) {
      emit(work, p, ring[0], ring[1], ring[2]);
      emit(work, p, ring[0], ring[2], ring[3]);
      return;
    }
    if (!folded && provenAnyTriangulation(leaf.cause) && triangulateRing(work, p, r, leaf.diagonal))
      return;
    // The fan's triangles need not keep to one diagonal: such a leaf's bound is then only
    // the any-triangle one (counted, docs/quadtree.md, "One diagonal").
    if (leaf.diagonal != gpu::kToleranceAnyDiagonal) ++work.out->diagonalFans;
    float us = leaf.split.x, vs = leaf.split.y;
    if (!(us > r.x && us < r.z && vs > r.y && vs < r.w)) {
      us = 0.5f * (r.x + r.z);
      vs = 0.5f * (r.y + r.w);
    }
    const RingVertex center = vertexAt(work, p, us, vs, kInside, false, true);
    for (size_t k = 0; k < ring.size(); ++k)
      emit(work, p, center, ring[k], ring[(k + 1) % ring.size()]);
  }

  SeamVertices& seams_;
  const PatchTopology& topology_;
  const LinePoints& lines_;
  const NearPointMerges& merges_;
  const HashSet<VertexKey, VertexKeyHash>& mergeTargets_;
};

}  // namespace

void walkLeaves(const LeafWalkTables& tables, const std::vector<QuadLeaf>& leaves, size_t begin,
                size_t end, uint32_t firstPatch, uint32_t endPatch, LeafRun& run) {
  LeafWalker(tables).walk(leaves, begin, end, firstPatch, endPatch, run);
}

}  // namespace tessera::triangulate_detail
