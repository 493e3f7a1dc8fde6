#include "mesh/ring_triangulation.h"

#include <limits>

#include "shaders/layout.h"

namespace tessera {
namespace {

// Which sides of the rectangle a point lies on: bit 0 v = lo.y, 1 u = hi.x, 2 v = hi.y,
// 3 u = lo.x (a corner has two); 0 when it is off the boundary. Exact comparisons: the
// triangulator places every ring point with one coordinate copied from the leaf's rectangle.
uint32_t sidesOf(glm::vec2 p, glm::vec2 lo, glm::vec2 hi) {
  if (!(p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y)) return 0;
  return (p.y == lo.y ? 1u : 0u) | (p.x == hi.x ? 2u : 0u) | (p.y == hi.y ? 4u : 0u) |
         (p.x == lo.x ? 8u : 0u);
}

// Position along the boundary, counter-clockwise from corner lo: 0..1 bottom, 1..2 right,
// 2..3 top, 3..4 left, in unit-square coordinates.
double boundaryPosition(glm::dvec2 s, uint32_t sides) {
  if ((sides & 1u) && s.x < 1.0) return s.x;
  if ((sides & 2u) && s.y < 1.0) return 1.0 + s.y;
  if ((sides & 4u) && s.x > 0.0) return 3.0 - s.x;
  return s.y > 0.0 ? 4.0 - s.y : 0.0;
}

// Whether p lies strictly inside side `side` (sidesOf's bit number) as triangulateRing sees it:
// on that side alone, its boundary position between the side's two corners'.
bool strictlyInsideSide(glm::vec2 p, uint32_t side, glm::vec2 lo, glm::vec2 hi) {
  if (sidesOf(p, lo, hi) != 1u << side) return false;
  const glm::dvec2 local = (glm::dvec2(p) - glm::dvec2(lo)) / (glm::dvec2(hi) - glm::dvec2(lo));
  const double position = boundaryPosition(local, 1u << side);
  return position > double(side) && position < double(side + 1);
}

// The working arrays of one thread's calls, kept from call to call: the triangulator asks once
// per leaf, and allocating them each time was most of the cost. They only grow (reserve), and
// are used through pointers: a ring's few points paid more for resize and push_back's checks
// than for the clipping itself.
struct RingWork {
  std::vector<uint32_t> sides, prev, next;
  std::vector<glm::dvec2> local;
  std::vector<double> position;  // boundaryPosition of each point
  std::vector<uint8_t> alive;
  std::vector<glm::vec2> half;  // triangulateRectangleRingAlong's halves
  std::vector<uint32_t> original;
  std::vector<std::array<uint32_t, 3>> halfTriangles;

  // Room for rings of n points.
  void reserve(size_t n) {
    if (sides.size() >= n) return;
    for (auto* v : {&sides, &prev, &next, &original}) v->resize(n);
    local.resize(n);
    position.resize(n);
    alive.resize(n);
    half.resize(n);
  }
};

RingWork& ringWork() {
  static thread_local RingWork work;
  return work;
}

// `ring`: n points (work.half may be it: only work's other arrays are written).
bool triangulateRing(const glm::vec2* ring, size_t n, glm::vec2 lo, glm::vec2 hi,
                     std::vector<std::array<uint32_t, 3>>& triangles, RingWork& work) {
  triangles.clear();
  if (n < 3 || !(lo.x < hi.x && lo.y < hi.y)) return false;
  const glm::dvec2 origin(lo), size = glm::dvec2(hi) - glm::dvec2(lo);
  work.reserve(n);
  uint32_t* const sides = work.sides.data();
  glm::dvec2* const local = work.local.data();
  double* const position = work.position.data();
  for (size_t i = 0; i < n; ++i) {
    sides[i] = sidesOf(ring[i], lo, hi);
    if (sides[i] == 0) return false;
    local[i] = (glm::dvec2(ring[i]) - origin) / size;
    position[i] = boundaryPosition(local[i], sides[i]);
  }
  uint32_t descents = position[0] <= position[n - 1];  // a ring of distinct points wraps once
  for (size_t i = 0; i + 1 < n; ++i) descents += position[i + 1] <= position[i];
  if (descents != 1) return false;
  if (n == 3) {  // the one ear, as the clipping below would give it, unless on one side
    if (sides[0] & sides[1] & sides[2]) return false;
    triangles.push_back({2, 0, 1});
    return true;
  }

  uint32_t* const prev = work.prev.data();
  uint32_t* const next = work.next.data();
  uint8_t* const alive = work.alive.data();
  uint32_t onSide[4] = {0, 0, 0, 0};  // points left on each side
  for (size_t i = 0; i < n; ++i) {
    alive[i] = 1;
    prev[i] = uint32_t(i == 0 ? n - 1 : i - 1);
    next[i] = uint32_t(i + 1 == n ? 0 : i + 1);
    for (int s = 0; s < 4; ++s) onSide[s] += (sides[i] >> s) & 1u;
  }
  for (int s = 0; s < 4; ++s)
    if (onSide[s] == n) return false;  // the whole ring on one side: nothing to cover
  triangles.reserve(n - 2);
  for (size_t left = n; left > 3; --left) {
    size_t best = n;
    double shortest = std::numeric_limits<double>::infinity();
    // The sides whose points would be all the other left − 1 points with point i gone: those
    // holding left − 1 points and not i, or left points and i.
    uint32_t flatWithout = 0, flatWith = 0;
    for (uint32_t s = 0; s < 4; ++s) {
      flatWithout |= uint32_t(onSide[s] == left - 1) << s;
      flatWith |= uint32_t(onSide[s] == left) << s;
    }
    for (size_t i = 0; i < n; ++i) {
      if (!alive[i]) continue;
      const uint32_t a = prev[i], c = next[i];
      if (sides[a] & sides[i] & sides[c]) continue;  // collinear: zero area
      if ((~sides[i] & flatWithout) | (sides[i] & flatWith)) continue;  // leftover on one side
      const glm::dvec2 d = local[c] - local[a];
      const double length2 = glm::dot(d, d);
      if (length2 < shortest) shortest = length2, best = i;
    }
    // A convex ring not on one line always has an ear: a corner off the line of the others,
    // or, when all others are on one line, that line's end next to it.
    if (best == n) return triangles.clear(), false;
    const uint32_t a = prev[best], c = next[best];
    triangles.push_back({a, uint32_t(best), c});
    alive[best] = 0;
    next[a] = c;
    prev[c] = a;
    for (int s = 0; s < 4; ++s) onSide[s] -= (sides[best] >> s) & 1u;
  }
  for (uint32_t i = 0; i < n; ++i)
    if (alive[i]) {
      triangles.push_back({prev[i], i, next[i]});
      break;
    }
  return true;
}

}  // namespace

bool triangulateRectangleRing(const std::vector<glm::vec2>& ring, glm::vec2 lo, glm::vec2 hi,
                              std::vector<std::array<uint32_t, 3>>& triangles) {
  return triangulateRing(ring.data(), ring.size(), lo, hi, triangles, ringWork());
}

bool triangulateRectangleRingAlong(const glm::vec2* ring, size_t n, glm::vec2 lo, glm::vec2 hi,
                                   uint32_t diagonal,
                                   std::vector<std::array<uint32_t, 3>>& triangles) {
  RingWork& work = ringWork();
  if (diagonal == gpu::kToleranceAnyDiagonal)
    return triangulateRing(ring, n, lo, hi, triangles, work);
  triangles.clear();
  const bool mainDiagonal = diagonal == gpu::kToleranceMainDiagonal;
  if (!mainDiagonal && diagonal != gpu::kToleranceAntiDiagonal) return false;
  const glm::vec2 from = mainDiagonal ? lo : glm::vec2(hi.x, lo.y);
  const glm::vec2 to = mainDiagonal ? hi : glm::vec2(lo.x, hi.y);
  size_t a = n, b = n;
  for (size_t i = 0; i < n; ++i) {
    if (ring[i] == from) a = i;
    if (ring[i] == to) b = i;
  }
  if (a == n || b == n || a == b) return false;
  // Each half: the ring from one diagonal corner to the other, counter-clockwise.
  work.reserve(n);
  glm::vec2* const half = work.half.data();
  uint32_t* const original = work.original.data();
  std::vector<std::array<uint32_t, 3>>& halfTriangles = work.halfTriangles;
  // Per half: the corner between the diagonal's two, and the first of its two sides (sidesOf's
  // bit numbers), counter-clockwise.
  const glm::vec2 corners[2] = {mainDiagonal ? glm::vec2(hi.x, lo.y) : hi,
                                mainDiagonal ? glm::vec2(lo.x, hi.y) : lo};
  const uint32_t firstSides[2] = {mainDiagonal ? 0u : 1u, mainDiagonal ? 2u : 3u};
  const bool positive = lo.x < hi.x && lo.y < hi.y;
  for (const auto& [start, end] : {std::pair{a, b}, std::pair{b, a}}) {
    size_t count = 0;
    for (size_t i = start;; i = i + 1 == n ? 0 : i + 1) {
      half[count] = ring[i];
      original[count++] = uint32_t(i);
      if (i == end) break;
    }
    // Most halves are three corners, or those and one point inside a side: what
    // triangulateRing gives them, without its setup (~150 and ~550 instructions a half). With
    // one point, one ear only keeps off a side, from both its ends alike: the first in ring
    // order goes first (test_ring_triangulation.cpp checks these against triangulateRing).
    const uint32_t* o = original;
    const glm::vec2 corner = corners[start != a];
    const uint32_t firstSide = firstSides[start != a];
    if (positive && count == 3 && half[1] == corner) {
      triangles.push_back({o[2], o[0], o[1]});
      continue;
    }
    if (positive && count == 4 && half[2] == corner &&
        strictlyInsideSide(half[1], firstSide, lo, hi)) {
      triangles.push_back({o[3], o[0], o[1]});
      triangles.push_back({o[3], o[1], o[2]});
      continue;
    }
    if (positive && count == 4 && half[1] == corner &&
        strictlyInsideSide(half[2], (firstSide + 1) % 4, lo, hi)) {
      triangles.push_back({o[0], o[1], o[2]});
      triangles.push_back({o[3], o[0], o[2]});
      continue;
    }
    if (!triangulateRing(half, count, lo, hi, halfTriangles, work)) return triangles.clear(), false;
    for (const auto& t : halfTriangles)
      triangles.push_back({original[t[0]], original[t[1]], original[t[2]]});
  }
  return true;
}

}  // namespace tessera
