#include "trim/gap_triangulate.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>

#include "common/small_id_list.h"
#include "trim/detail/flip_edge_table.h"
#include "trim/trim_cut.h"

namespace tessera {
namespace {

constexpr double kPi = 3.14159265358979323846;

double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

// The counter-clockwise angle from `from` to `to`, in [0, 2π).
double ccwAngle(glm::dvec2 from, glm::dvec2 to) {
  double angle = std::atan2(cross(from, to), glm::dot(from, to));
  return angle < 0 ? angle + 2 * kPi : angle;
}

double signedArea(const std::vector<glm::dvec2>& points, const std::vector<uint32_t>& loop) {
  double area = 0;
  for (size_t k = 0; k < loop.size(); ++k)
    area += cross(points[loop[k]], points[loop[(k + 1) % loop.size()]]);
  return 0.5 * area;
}

// Edges → closed loops of vertex ids.
std::vector<std::vector<uint32_t>> closedLoops(
    const std::vector<glm::dvec2>& points,
    const std::vector<std::pair<uint32_t, uint32_t>>& edges, size_t& failures) {
  // Each vertex's outgoing edges in their given order, as a std::multimap gave them: grouped
  // by a counting sort (edge ids < points.size()), looked up by the vertex without a search.
  std::vector<uint32_t> outFrom(points.size() + 1, 0), outgoing(edges.size());
  for (const auto& e : edges) ++outFrom[e.first + 1];
  for (size_t v = 0; v < points.size(); ++v) outFrom[v + 1] += outFrom[v];
  {
    std::vector<uint32_t> fill(outFrom.begin(), outFrom.end() - 1);
    for (uint32_t e = 0; e < edges.size(); ++e) outgoing[fill[edges[e].first]++] = e;
  }
  std::vector<bool> used(edges.size(), false);
  std::vector<std::vector<uint32_t>> loops;
  // The loop walked in a buffer kept for the thread and copied out at its size once closed (a
  // vector grown by push_back reallocated log n times per loop).
  thread_local std::vector<uint32_t> loop;
  for (uint32_t start = 0; start < edges.size(); ++start) {
    if (used[start]) continue;
    loop.assign(1, edges[start].first);
    used[start] = true;
    uint32_t from = edges[start].first, at = edges[start].second;
    bool closed = false;
    for (size_t steps = 0; steps <= edges.size(); ++steps) {
      // The way on that turns first clockwise from the way back keeps the region on the left.
      const uint32_t* const first = outgoing.data() + outFrom[at];
      const uint32_t* const last = outgoing.data() + outFrom[at + 1];
      const auto open = [&](uint32_t e) { return !used[e] || e == start; };
      int64_t best = -1;
      // One way on (nearly every vertex) is the way, whatever its angle: no angles measured.
      const bool only = std::count_if(first, last, open) == 1;
      if (only) best = *std::find_if(first, last, open);
      const glm::dvec2 back = points[from] - points[at];
      double bestAngle = 0;
      for (const uint32_t* it = first; it != last && !only; ++it) {
        const uint32_t e = *it;
        if (!open(e)) continue;
        const glm::dvec2 way = points[edges[e].second] - points[at];
        double clockwise = 2 * kPi - ccwAngle(back, way);  // in (0, 2π]
        if (best < 0 || clockwise < bestAngle) best = e, bestAngle = clockwise;
      }
      if (best < 0) break;
      if (uint32_t(best) == start) {
        closed = true;
        break;
      }
      used[best] = true;
      loop.push_back(at);
      from = at;
      at = edges[best].second;
    }
    if (closed && loop.size() >= 3)
      loops.emplace_back(loop.begin(), loop.end());
    else
      ++failures;
  }
  return loops;
}

// ccwAngle(next − at, prev − at): the region's angle at vertex `at` (insideWedge's).
double wedgeAngle(glm::dvec2 prev, glm::dvec2 at, glm::dvec2 next) {
  return ccwAngle(next - at, prev - at);
}

// Whether direction d leaves vertex `at` into the region (strictly between its edges); `wedge`
// is wedgeAngle(prev, at, next).
bool insideWedge(double wedge, glm::dvec2 at, glm::dvec2 next, glm::dvec2 d) {
  const double angle = ccwAngle(next - at, d);
  return angle > 0 && angle < (wedge == 0 ? 2 * kPi : wedge);
}

// A run of consecutive edges of bridgeHole's list, with the box and the largest |coordinate| of
// their ends.
struct EdgeRun {
  glm::dvec2 lo, hi, reach;
  uint32_t begin, end;
  bool boxed = true;  // false: lo, hi and reach unknown (a point not finite)
};

// The edges in runs of 8 (consecutive edges of a loop lie near each other); none when a point
// is not finite (then every edge is tested).
std::vector<EdgeRun> edgeRuns(const std::vector<glm::dvec2>& points,
                              const std::vector<std::pair<uint32_t, uint32_t>>& edges) {
  constexpr uint32_t kRun = 8;
  std::vector<EdgeRun> runs;
  runs.reserve(edges.size() / kRun + 1);
  for (uint32_t begin = 0; begin < edges.size(); begin += kRun) {
    const uint32_t end = std::min(uint32_t(edges.size()), begin + kRun);
    EdgeRun run{points[edges[begin].first], points[edges[begin].first], glm::dvec2(0.0), begin, end};
    for (uint32_t e = begin; e < end; ++e)
      for (const glm::dvec2 q : {points[edges[e].first], points[edges[e].second]}) {
        if (!(std::isfinite(q.x) && std::isfinite(q.y)))
          return {EdgeRun{{}, {}, {}, 0, uint32_t(edges.size()), false}};
        run.lo = glm::min(run.lo, q), run.hi = glm::max(run.hi, q);
        run.reach = glm::max(run.reach, glm::abs(q));
      }
    runs.push_back(run);
  }
  return runs;
}

// Whether segmentsFartherThan(a, b, q0, q1, touch) holds for every edge (q0, q1) of the run,
// from its box alone. Its crossing test needs the two signs of cross(b − a, q − a) at q0 and q1
// to differ; that rounded cross product is monotone in q.x and in q.y (as boxOutsideTriangle's),
// so when it is > 0 at the box's corner where it is least (or < 0 where it is largest), no two
// ends in the box differ. Its box test then passes for every edge: each edge's gap to a → b is
// at least the run's, and its allowance for rounding at most the run's (rounding is monotone).
// A run not a whole way off the line a → b, or too near, says false: its edges are tested.
bool runClear(const EdgeRun& run, glm::dvec2 a, glm::dvec2 b, double touch) {
  if (!run.boxed) return false;
  const glm::dvec2 e = b - a;
  const glm::dvec2 least(e.y >= 0 ? run.hi.x : run.lo.x, e.x >= 0 ? run.lo.y : run.hi.y);
  const glm::dvec2 largest(e.y >= 0 ? run.lo.x : run.hi.x, e.x >= 0 ? run.hi.y : run.lo.y);
  if (!(cross(e, least - a) > 0 || cross(e, largest - a) < 0)) return false;
  const glm::dvec2 lo = glm::min(a, b), hi = glm::max(a, b);
  const glm::dvec2 apart = glm::max(run.lo - hi, lo - run.hi);
  const glm::dvec2 m = glm::max(glm::max(glm::abs(a), glm::abs(b)), run.reach);
  return std::max(apart.x, apart.y) > touch + 1e-12 * std::max(m.x, m.y);
}

// Joins `hole` into `polygon` by a bridge from the nearest hole vertex visible from a polygon
// vertex. `others` are the edges of holes still to join: the bridge must cross none of them.
bool bridgeHole(const std::vector<glm::dvec2>& points, std::vector<uint32_t>& polygon,
                const std::vector<uint32_t>& hole,
                const std::vector<std::pair<uint32_t, uint32_t>>& others, double scale) {
  struct Candidate {
    double distance;
    uint32_t p, h;
  };
  std::vector<Candidate> candidates;
  candidates.reserve(polygon.size() * hole.size());
  for (size_t p = 0; p < polygon.size(); ++p)
    for (size_t h = 0; h < hole.size(); ++h)
      candidates.push_back(
          {glm::length(points[polygon[p]] - points[hole[h]]), uint32_t(p), uint32_t(h)});
  const double touch = 1e-13 * scale;
  auto clear = [&](uint32_t a, uint32_t b, uint32_t e0, uint32_t e1) {
    const glm::dvec2 pa = points[a], pb = points[b], q0 = points[e0], q1 = points[e1];
    if (q0 == pa || q0 == pb || q1 == pa || q1 == pb) return true;  // an edge at an end
    return segmentsFartherThan(pa, pb, q0, q1, touch);
  };
  const size_t n = polygon.size(), k = hole.size();
  // Each vertex's wedge once (a candidate asks for it again for every vertex across).
  std::vector<double> polygonWedge(n, -1.0), holeWedge(k, -1.0);
  const auto wedgeOf = [&](std::vector<double>& wedges, const std::vector<uint32_t>& ring,
                           size_t i) {
    const size_t size = ring.size();
    if (wedges[i] < 0)
      wedges[i] = wedgeAngle(points[ring[(i + size - 1) % size]], points[ring[i]],
                             points[ring[(i + 1) % size]]);
    return wedges[i];
  };
  // The edges that may block a bridge (the polygon's, the hole's, the other holes'), in runs of
  // a few with their box: a run that no edge of can block is passed at once (runClear).
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  edges.reserve(n + k + others.size());
  for (size_t e = 0; e < n; ++e) edges.push_back({polygon[e], polygon[(e + 1) % n]});
  for (size_t e = 0; e < k; ++e) edges.push_back({hole[e], hole[(e + 1) % k]});
  edges.insert(edges.end(), others.begin(), others.end());
  const std::vector<EdgeRun> runs = edgeRuns(points, edges);
  const auto bridges = [&](const Candidate& c) {
    const uint32_t p = polygon[c.p], m = hole[c.h];
    if (p == m || points[p] == points[m]) return p == m;  // two ids at one place: no bridge
    const glm::dvec2 d = points[m] - points[p];
    if (!insideWedge(wedgeOf(polygonWedge, polygon, c.p), points[p],
                     points[polygon[(c.p + 1) % n]], d))
      return false;
    if (!insideWedge(wedgeOf(holeWedge, hole, c.h), points[m], points[hole[(c.h + 1) % k]], -d))
      return false;
    // Every edge clear, in any order: clear() is a function of the points alone.
    for (const EdgeRun& run : runs) {
      if (runClear(run, points[p], points[m], touch)) continue;
      for (uint32_t e = run.begin; e < run.end; ++e)
        if (!clear(p, m, edges[e].first, edges[e].second)) return false;
    }
    return true;
  };
  const auto join = [&](const Candidate& c) {
    // polygon[..p], m round the hole back to m, p again, the rest of the polygon (p == m: the
    // hole is spliced in at its shared vertex, which then appears twice).
    const uint32_t p = polygon[c.p], m = hole[c.h];
    std::vector<uint32_t> joined(polygon.begin(), polygon.begin() + c.p + 1);
    for (size_t j = (p == m ? 1 : 0); j <= k; ++j) joined.push_back(hole[(c.h + j) % k]);
    if (p != m) joined.push_back(p);
    joined.insert(joined.end(), polygon.begin() + c.p + 1, polygon.end());
    polygon = std::move(joined);
    return true;
  };
  // The first candidate that bridges, nearest first in std::sort's order. Taken from a heap
  // instead (the first few usually bridge; sorting them all was a tenth of the gap's time): the
  // heap's first that bridges is the sorted loop's when no other candidate has its distance, as
  // every nearer one failed in both; with ties, the order among them is the sort's own, so the
  // sorted loop then runs as it did. Which of several at one distance the heap gives first does
  // not matter (any of them that bridges sends the search to the sort), so the nearest, when it
  // alone has its distance and bridges (most holes), is the answer, found in one pass without
  // the heap's copy and build.
  const auto nearer = [](const Candidate& a, const Candidate& b) { return a.distance < b.distance; };
  const auto farther = [](const Candidate& a, const Candidate& b) { return a.distance > b.distance; };
  size_t nearest = 0, atNearest = 0;  // the first nearest candidate, and how many share its distance
  for (size_t c = 0; c < candidates.size(); ++c) {
    if (c == 0 || candidates[c].distance < candidates[nearest].distance)
      nearest = c, atNearest = 1;
    else if (candidates[c].distance == candidates[nearest].distance)
      ++atNearest;
  }
  if (atNearest == 1 && bridges(candidates[nearest])) return join(candidates[nearest]);
  std::vector<Candidate> heap = candidates;
  std::make_heap(heap.begin(), heap.end(), farther);
  bool tied = false;
  while (!heap.empty() && !tied) {
    std::pop_heap(heap.begin(), heap.end(), farther);
    const Candidate c = heap.back();
    heap.pop_back();
    if (!bridges(c)) continue;
    size_t same = 0;
    for (const Candidate& other : candidates) same += other.distance == c.distance;
    if (same == 1) return join(c);
    tied = true;
  }
  if (!tied) return false;  // none bridges, in any order
  std::sort(candidates.begin(), candidates.end(), nearer);
  for (const Candidate& c : candidates)
    if (bridges(c)) return join(c);
  return false;
}

// A triangle whose height is under this share of its longest side is flat for the gap: three
// points that lie on one (u, v) line up to rounding (fp32 corner uvs leave a barely positive
// area). Such an ear or flip makes a 3D triangle across the surface's curve along that line
// that no midpoint split repairs (docs/trimmed_faces.md, "Slivers").
constexpr double kFlatRatio = 1e-5;

// 2·area / (longest side)² = height / longest side; negative when clockwise.
double shapeRatio(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
  const double longest2 =
      std::max({glm::dot(b - a, b - a), glm::dot(c - b, c - b), glm::dot(a - c, a - c)});
  return longest2 > 0 ? cross(b - a, c - a) / longest2 : 0.0;
}

bool insideOrOnTriangle(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
  return cross(b - a, p - a) >= 0 && cross(c - b, p - b) >= 0 && cross(a - c, p - c) >= 0;
}

// Whether insideOrOnTriangle(p, a, b, c) is false for every p in the box [lo, hi], as rounded.
// Each side's rounded cross(e, p − o) = e.x ⊗ (p.y ⊖ o.y) ⊖ e.y ⊗ (p.x ⊖ o.x) is monotone in
// p.x and in p.y (rounding is monotone, and so is each step for a fixed e), so over the box it is
// largest at the corner that e's signs pick: where that is < 0, it is < 0 for every point in
// the box. (NaN there: not < 0, so never rejects.)
bool boxOutsideTriangle(glm::dvec2 lo, glm::dvec2 hi, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
  const auto sideRejects = [&](glm::dvec2 o, glm::dvec2 to) {
    const glm::dvec2 e = to - o;
    const glm::dvec2 p(e.y >= 0 ? lo.x : hi.x, e.x >= 0 ? hi.y : lo.y);
    return cross(e, p - o) < 0;
  };
  return sideRejects(a, b) || sideRejects(b, c) || sideRejects(c, a);
}

// The polygon's positions in the cells of a grid over its points, each cell with the tight box
// of its points: an ear test skips a whole cell when boxOutsideTriangle says none of its points
// passes, and tests the others' points as the scan over every vertex does. Any vertex found
// inside serves as the corner's blocker (EarCorner): a corner is blocked while any vertex lies
// in its ear, so the corners' findings, and the ears clipped, are those of the plain scan.
class EarGrid {
 public:
  EarGrid() = default;  // not usable: the plain scan
  EarGrid(const std::vector<glm::dvec2>& points, const std::vector<uint32_t>& polygon) {
    const size_t count = polygon.size();
    glm::dvec2 lo = points[polygon[0]], hi = lo;
    for (uint32_t id : polygon) {
      const glm::dvec2 p = points[id];
      if (!(std::isfinite(p.x) && std::isfinite(p.y))) return;  // the plain scan
      lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
    const glm::dvec2 extent = hi - lo;
    if (!(std::isfinite(extent.x) && std::isfinite(extent.y))) return;
    const size_t side = size_t(std::ceil(std::sqrt(double(count) / 4)));
    const auto cellOf = [&](glm::dvec2 p) {
      const auto index = [&](double x, double from, double width) {
        if (!(width > 0)) return size_t(0);
        return std::min(side - 1, size_t(double(side) * ((x - from) / width)));
      };
      return index(p.y, lo.y, extent.y) * side + index(p.x, lo.x, extent.x);
    };
    std::vector<uint32_t> cellOfPosition(count), start(side * side + 1, 0);
    for (size_t i = 0; i < count; ++i) ++start[(cellOfPosition[i] = uint32_t(cellOf(points[polygon[i]]))) + 1];
    for (size_t k = 0; k < side * side; ++k) start[k + 1] += start[k];
    positions_.resize(count);
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (uint32_t i = 0; i < count; ++i) positions_[fill[cellOfPosition[i]]++] = i;
    for (size_t k = 0; k < side * side; ++k) {
      if (start[k] == start[k + 1]) continue;
      Cell cell{points[polygon[positions_[start[k]]]], points[polygon[positions_[start[k]]]],
                start[k], start[k + 1]};
      for (uint32_t q = start[k]; q < start[k + 1]; ++q) {
        const glm::dvec2 p = points[polygon[positions_[q]]];
        cell.lo = glm::min(cell.lo, p), cell.hi = glm::max(cell.hi, p);
      }
      cells_.push_back(cell);
    }
    usable_ = true;
  }
  bool usable() const { return usable_; }
  // A position left (`left`) whose point passes insideOrOnTriangle and is none of a, b, c, or
  // none (~0u).
  template <class At>
  uint32_t blocker(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, const std::vector<char>& left,
                   At at) const {
    for (const Cell& cell : cells_) {
      if (boxOutsideTriangle(cell.lo, cell.hi, a, b, c)) continue;
      for (uint32_t q = cell.begin; q < cell.end; ++q) {
        const uint32_t j = positions_[q];
        if (!left[j]) continue;
        const glm::dvec2 p = at(j);
        if (insideOrOnTriangle(p, a, b, c) && !(p == a || p == b || p == c)) return j;
      }
    }
    return ~0u;
  }

 private:
  struct Cell {
    glm::dvec2 lo, hi;
    uint32_t begin, end;  // into positions_
  };
  std::vector<Cell> cells_;
  std::vector<uint32_t> positions_;  // grouped by cell
  bool usable_ = false;
};

// Below this many vertices the plain scan is as fast as the grid.
constexpr size_t kEarGridFrom = 48;

// One corner of the polygon being clipped, with what the ear test last found there. The
// polygon only loses vertices, so the finding holds until the corner's neighbours change (a new
// triangle) or, for a blocked corner, until its blocker is clipped away: an empty ear stays
// empty, and a corner with a vertex inside stays blocked while that vertex is left.
struct EarCorner {
  enum Kind : uint8_t { Unknown, Reflex, Blocked, Ear, Flat };
  uint32_t prev = 0, next = 0;  // neighbours, as positions in the polygon given
  Kind kind = Unknown;
  uint32_t blocker = 0;  // Blocked: the position of a vertex inside or on the ear
  double area = 0;       // cross(b − a, c − b) of (prev, this, next): > 0 when convex
  double ratio = 0;      // shapeRatio, for an empty ear
};

// Ear clipping of a weakly simple counter-clockwise polygon (ids may repeat at bridges and
// pinches). A vertex is an ear when its corner is strictly convex and no other vertex, at a
// place other than the ear's three corners, lies inside the ear or on its sides. The first ear
// in the polygon's order is clipped; a flat ear (kFlatRatio) is taken only when no other ear is
// left, the fattest of them first. The polygon is a linked list whose corners keep their ear
// test (EarCorner): re-testing every corner before the first ear after each clip, each against
// every vertex, was most of the gap's time.
void clipEars(const std::vector<glm::dvec2>& points, const std::vector<uint32_t>& polygon,
              std::vector<std::array<uint32_t, 3>>& triangles, size_t& failures) {
  const uint32_t count = uint32_t(polygon.size());
  if (count < 3) return;
  std::vector<EarCorner> corners(count);
  std::vector<char> left(count, 1);  // not clipped yet
  for (uint32_t i = 0; i < count; ++i)
    corners[i].prev = (i + count - 1) % count, corners[i].next = (i + 1) % count;
  uint32_t head = 0, size = count;  // head: the first vertex left, in the polygon's order
  const auto at = [&](uint32_t i) { return points[polygon[i]]; };
  const EarGrid grid = count >= kEarGridFrom ? EarGrid(points, polygon) : EarGrid();
  // The corner's ear test, re-done only when what it found may no longer hold.
  const auto test = [&](uint32_t i) -> const EarCorner& {
    EarCorner& corner = corners[i];
    if (corner.kind != EarCorner::Unknown &&
        !(corner.kind == EarCorner::Blocked && !left[corner.blocker]))
      return corner;
    const glm::dvec2 a = at(corner.prev), b = at(i), c = at(corner.next);
    corner.area = cross(b - a, c - b);
    if (corner.area <= 0) {
      corner.kind = EarCorner::Reflex;
      return corner;
    }
    if (grid.usable()) {
      const uint32_t j = grid.blocker(a, b, c, left, at);
      if (j != ~0u) {
        corner.kind = EarCorner::Blocked, corner.blocker = j;
        return corner;
      }
      corner.ratio = shapeRatio(a, b, c);
      corner.kind = corner.ratio >= kFlatRatio ? EarCorner::Ear : EarCorner::Flat;
      return corner;
    }
    uint32_t j = head;
    for (uint32_t k = 0; k < size; ++k, j = corners[j].next) {
      // Inside first: most vertices fail its first side, and fewer then need the three
      // comparisons with the corners (the same answer in either order).
      const glm::dvec2 p = at(j);
      if (insideOrOnTriangle(p, a, b, c) && !(p == a || p == b || p == c)) {
        corner.kind = EarCorner::Blocked, corner.blocker = j;
        return corner;
      }
    }
    corner.ratio = shapeRatio(a, b, c);
    corner.kind = corner.ratio >= kFlatRatio ? EarCorner::Ear : EarCorner::Flat;
    return corner;
  };
  while (size > 3) {
    constexpr uint32_t kNone = ~0u;
    uint32_t ear = kNone, fallback = kNone, flat = kNone;
    double fallbackArea = 0, flatRatio = 0;
    uint32_t i = head;
    for (uint32_t k = 0; k < size && ear == kNone; ++k, i = corners[i].next) {
      const EarCorner& corner = test(i);
      if (corner.kind == EarCorner::Reflex) continue;
      if (corner.area > fallbackArea) fallback = i, fallbackArea = corner.area;
      if (corner.kind == EarCorner::Ear)
        ear = i;
      else if (corner.kind == EarCorner::Flat && corner.ratio > flatRatio)
        flat = i, flatRatio = corner.ratio;
    }
    if (ear == kNone) ear = flat;
    if (ear == kNone) {
      ++failures;
      if (fallback == kNone) return;  // nothing convex is left: a degenerate remainder
      ear = fallback;
    }
    const uint32_t before = corners[ear].prev, after = corners[ear].next;
    triangles.push_back({polygon[before], polygon[ear], polygon[after]});
    left[ear] = 0, --size;
    corners[before].next = after, corners[after].prev = before;
    corners[before].kind = corners[after].kind = EarCorner::Unknown;  // a new triangle each
    if (head == ear) head = after;
  }
  const uint32_t v0 = head, v1 = corners[v0].next, v2 = corners[v1].next;
  const double area = cross(at(v1) - at(v0), at(v2) - at(v1));
  if (area > 0)
    triangles.push_back({polygon[v0], polygon[v1], polygon[v2]});
  else if (area < 0)
    ++failures;  // a clockwise remainder: the polygon crossed itself (a bow tie's other lobe)
}

}  // namespace

GapTriangulation triangulateGap(const std::vector<glm::dvec2>& points,
                                const std::vector<std::pair<uint32_t, uint32_t>>& edges) {
  GapTriangulation result;
  if (edges.empty()) return result;
  result.triangles.reserve(edges.size());  // about one a boundary edge, more with holes
  std::vector<std::vector<uint32_t>> loops = closedLoops(points, edges, result.failures);
  glm::dvec2 lo = points[edges[0].first], hi = lo;
  for (const auto& e : edges) lo = glm::min(lo, points[e.first]), hi = glm::max(hi, points[e.first]);
  const double scale = std::max(hi.x - lo.x, hi.y - lo.y);

  std::vector<size_t> outers, holes;
  std::vector<double> areas(loops.size());
  for (size_t l = 0; l < loops.size(); ++l) {
    areas[l] = signedArea(points, loops[l]);
    (areas[l] > 0 ? outers : holes).push_back(l);
  }
  std::vector<std::vector<size_t>> holesOf(loops.size());
  std::vector<std::vector<TrimSegment>> outerSegments;  // per outer loop, built once
  if (!holes.empty())
    for (size_t o : outers) {
      std::vector<TrimSegment>& segments = outerSegments.emplace_back();
      segments.reserve(loops[o].size());
      for (size_t k = 0; k < loops[o].size(); ++k)
        segments.push_back({points[loops[o][k]], points[loops[o][(k + 1) % loops[o].size()]]});
    }
  for (size_t h : holes) {
    // A point of the hole's boundary: the middle of its first edge (on no other loop).
    const glm::dvec2 probe = 0.5 * (points[loops[h][0]] + points[loops[h][1]]);
    int64_t around = -1;
    for (size_t i = 0; i < outers.size(); ++i) {
      const size_t o = outers[i];
      if (trimWindingNumber(outerSegments[i], probe) > 0 &&
          (around < 0 || areas[o] < areas[around]))
        around = int64_t(o);
    }
    if (around < 0)
      ++result.failures;
    else
      holesOf[around].push_back(h);
  }
  for (size_t o : outers) {
    std::vector<uint32_t> polygon = loops[o];
    const std::vector<size_t>& inner = holesOf[o];
    for (size_t i = 0; i < inner.size(); ++i) {
      std::vector<std::pair<uint32_t, uint32_t>> others;
      for (size_t j = i + 1; j < inner.size(); ++j)
        for (size_t k = 0; k < loops[inner[j]].size(); ++k)
          others.push_back({loops[inner[j]][k], loops[inner[j]][(k + 1) % loops[inner[j]].size()]});
      if (!bridgeHole(points, polygon, loops[inner[i]], others, scale)) ++result.failures;
    }
    clipEars(points, polygon, result.triangles, result.failures);
  }
  flipTowardsDelaunay(points, edges, result.triangles);
  return result;
}

namespace {

using EdgeKey64 = uint64_t;  // an edge as one exact key: smaller vertex in the high word

void flipWith(const std::vector<glm::dvec2>& points,
              const std::vector<std::pair<uint32_t, uint32_t>>& fixed,
              std::vector<std::array<uint32_t, 3>>& triangles) {
  using Edge = EdgeKey64;
  using Entry = trim_detail::FlipEdgeTable::Entry;
  const auto key = [](uint32_t a, uint32_t b) {
    return Edge(std::min(a, b)) << 32 | Edge(std::max(a, b));
  };
  trim_detail::FlipEdgeTable users(triangles.size());  // edge → the triangles using it
  for (uint32_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      users[key(triangles[t][k], triangles[t][(k + 1) % 3])].ids.push_back(t);
  // The constrained edges marked in the table (Entry::fixed), once. A constrained edge is never
  // flipped, so never erased: a flip's new edge is constrained only if some input edge is
  // missing from the triangulation (a loop that did not close), and only then is it looked up
  // in the sorted list, a buffer kept for the thread like the queue (most gaps are a few
  // triangles, where allocations cost more than the flips).
  thread_local std::vector<Edge> missing;
  missing.clear();
  for (const auto& e : fixed) {
    const Edge edge = key(e.first, e.second);
    if (Entry* entry = users.find(edge))
      entry->fixed = true;
    else
      missing.push_back(edge);
  }
  std::sort(missing.begin(), missing.end());
  const auto isMissingConstrained = [&](Edge e) {
    return !missing.empty() && std::binary_search(missing.begin(), missing.end(), e);
  };
  thread_local std::vector<Edge> queue;
  queue.clear();
  // Every flip queues four edges: room for the first pass and a few flips, so the queue does not
  // grow by doubling from nothing (its reallocations were a tenth of the gap's time).
  queue.reserve(3 * triangles.size() + 64);
  users.forEach([&](Edge edge, const Entry& entry) {
    if (entry.ids.size() == 2 && !entry.fixed) queue.push_back(edge);
  });
  std::sort(queue.begin(), queue.end());  // a deterministic order, whatever the map's
  // Queues an edge of the triangulation (in the table) unless it is constrained.
  const auto queueFree = [&](Edge edge, const Entry& entry) {
    if (!entry.fixed) queue.push_back(edge);
  };
  // Each flip lowers the triangulation's lifted volume, so this ends; the cap is a guard
  // against rounding cycling two nearly cocircular flips.
  size_t budget = 64 * (triangles.size() + 1) * (triangles.size() + 1);
  while (!queue.empty() && budget-- > 0) {
    const Edge edge = queue.back();
    queue.pop_back();
    const Entry* found = users.find(edge);
    if (!found || found->ids.size() != 2 || found->fixed) continue;
    const uint32_t t0 = found->ids[0], t1 = found->ids[1];
    // t0 = (a, b, c) counter-clockwise with the edge a→b; t1 holds b→a and d.
    int k0 = 0;
    while (key(triangles[t0][k0], triangles[t0][(k0 + 1) % 3]) != edge) ++k0;
    const uint32_t a = triangles[t0][k0], b = triangles[t0][(k0 + 1) % 3],
                   c = triangles[t0][(k0 + 2) % 3];
    const uint32_t d = triangles[t1][0] + triangles[t1][1] + triangles[t1][2] - a - b;
    if (d == c) continue;
    const glm::dvec2 pa = points[a], pb = points[b], pc = points[c], pd = points[d];
    // d in the circumcircle of the counter-clockwise (a, b, c): the in-circle determinant > 0.
    const glm::dvec2 ad = pa - pd, bd = pb - pd, cd = pc - pd;
    const double inCircle = glm::dot(ad, ad) * cross(bd, cd) - glm::dot(bd, bd) * cross(ad, cd) +
                            glm::dot(cd, cd) * cross(ad, bd);
    const double scale2 = glm::dot(ad, ad) + glm::dot(bd, bd) + glm::dot(cd, cd);
    if (!(inCircle > 1e-12 * scale2 * scale2)) continue;
    // The new triangles (c, a, d) and (d, b, c) must both be counter-clockwise, and not flat.
    if (!(shapeRatio(pc, pa, pd) >= kFlatRatio && shapeRatio(pd, pb, pc) >= kFlatRatio)) continue;
    triangles[t0] = {c, a, d};
    triangles[t1] = {d, b, c};
    users.erase(edge);
    Entry& newEdge = users[key(c, d)];
    newEdge.ids = SmallIdList(t0, t1);
    if (isMissingConstrained(key(c, d))) newEdge.fixed = true;  // else as it was, if present
    Entry& aToD = users[key(a, d)];
    aToD.ids.replace(t1, t0);
    Entry& bToC = users[key(b, c)];
    bToC.ids.replace(t0, t1);
    // The four sides of the quadrilateral, all edges of t0 or t1, in this order: the queue is a
    // stack, and its order is the flips'.
    queueFree(key(a, c), *users.find(key(a, c)));
    queueFree(key(a, d), aToD);
    queueFree(key(b, c), bToC);
    queueFree(key(b, d), *users.find(key(b, d)));
  }
}

}  // namespace

void flipTowardsDelaunay(const std::vector<glm::dvec2>& points,
                         const std::vector<std::pair<uint32_t, uint32_t>>& fixed,
                         std::vector<std::array<uint32_t, 3>>& triangles) {
  if (triangles.size() < 2) return;  // no edge has two triangles
  flipWith(points, fixed, triangles);
}

}  // namespace tessera
