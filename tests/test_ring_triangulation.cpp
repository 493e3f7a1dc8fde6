// ring_triangulation.h: a leaf's ring (corners plus the points its neighbours put on its sides)
// becomes n − 2 counter-clockwise triangles that cover the rectangle exactly, none of zero area,
// for every count of points per side, also with every edge along one diagonal.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "mesh/ring_triangulation.h"

using namespace tessera;

namespace {

// The ring of a rectangle with these points strictly inside each side (fractions of the side,
// ascending), counter-clockwise from corner lo as the triangulator builds it.
std::vector<glm::vec2> ringOf(glm::vec2 lo, glm::vec2 hi,
                              const std::array<std::vector<float>, 4>& inner) {
  std::vector<glm::vec2> ring;
  const auto at = [&](float s, float t) {
    return glm::vec2(lo.x + (hi.x - lo.x) * s, lo.y + (hi.y - lo.y) * t);
  };
  ring.push_back(lo);
  for (float f : inner[0]) ring.push_back({at(f, 0).x, lo.y});
  ring.push_back({hi.x, lo.y});
  for (float f : inner[1]) ring.push_back({hi.x, at(0, f).y});
  ring.push_back(hi);
  for (auto it = inner[2].rbegin(); it != inner[2].rend(); ++it)
    ring.push_back({at(*it, 0).x, hi.y});
  ring.push_back({lo.x, hi.y});
  for (auto it = inner[3].rbegin(); it != inner[3].rend(); ++it)
    ring.push_back({lo.x, at(0, *it).y});
  return ring;
}

double doubledArea(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Everything the triangulation promises, checked independently of how it was made: n − 2
// triangles, each counter-clockwise with positive area; ring edges used once in ring order,
// every other edge once each way (so the triangles tile the polygon without gaps or overlaps);
// areas summing to the rectangle's. With a diagonal (1 main, 2 anti: triangulateRectangleRing-
// Along), every edge also has Δu·Δv ≥ 0 (main) or ≤ 0 (anti), the property rule T's diagonal
// bound needs. Returns the smallest area / the rectangle's.
double checkRing(const std::vector<glm::vec2>& ring, glm::vec2 lo, glm::vec2 hi,
                 uint32_t diagonal = 0) {
  std::vector<std::array<uint32_t, 3>> triangles;
  REQUIRE(triangulateRectangleRingAlong(ring, lo, hi, diagonal, triangles));
  const size_t n = ring.size();
  REQUIRE(triangles.size() == n - 2);
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  double total = 0, smallest = 1e300;
  for (const auto& t : triangles) {
    for (uint32_t k : t) REQUIRE(k < n);
    const double area = 0.5 * doubledArea(ring[t[0]], ring[t[1]], ring[t[2]]);
    REQUIRE(area > 0.0);
    total += area;
    smallest = std::min(smallest, area);
    for (int k = 0; k < 3; ++k) {
      ++directed[{t[k], t[(k + 1) % 3]}];
      const glm::dvec2 d = glm::dvec2(ring[t[(k + 1) % 3]]) - glm::dvec2(ring[t[k]]);
      if (diagonal == 1) REQUIRE(d.x * d.y >= 0.0);
      if (diagonal == 2) REQUIRE(d.x * d.y <= 0.0);
    }
  }
  for (const auto& [edge, count] : directed) {
    REQUIRE(count == 1);
    const bool ringEdge = (edge.first + 1) % n == edge.second;
    if (!ringEdge) REQUIRE(directed.count({edge.second, edge.first}) == 1);
  }
  for (uint32_t i = 0; i < n; ++i) REQUIRE(directed.count({i, uint32_t((i + 1) % n)}) == 1);
  const double rectangle = (double(hi.x) - lo.x) * (double(hi.y) - lo.y);
  CHECK(std::fabs(total - rectangle) <= 1e-12 * rectangle);
  return smallest / rectangle;
}

}  // namespace

TEST_CASE("every ring shape with 0..4 points per side triangulates without a new vertex",
          "[ring]") {
  const std::pair<glm::vec2, glm::vec2> rectangles[] = {
      {{0, 0}, {1, 1}},
      {{0.25f, 0.5f}, {0.3125f, 0.5078125f}},  // a deep, anisotropic leaf
      {{0.6f, 0.1f}, {0.7f, 0.9f}},            // widths that fp32 rounds
  };
  std::mt19937 random(15);
  std::uniform_int_distribution<int> sixtyFourths(1, 63);
  size_t shapes = 0;
  double smallest[3] = {1, 1, 1};
  for (const auto& [lo, hi] : rectangles)
    for (int counts = 0; counts < 5 * 5 * 5 * 5; ++counts)
      for (bool even : {true, false}) {
        std::array<std::vector<float>, 4> inner;
        for (int side = 0, c = counts; side < 4; ++side, c /= 5) {
          const int k = c % 5;
          for (int i = 1; i <= k; ++i) inner[side].push_back(float(i) / float(k + 1));
          if (!even) {  // uneven spacing, as a mix of finer neighbours gives
            for (float& f : inner[side]) f = float(sixtyFourths(random)) / 64.0f;
            std::sort(inner[side].begin(), inner[side].end());
            inner[side].erase(std::unique(inner[side].begin(), inner[side].end()),
                              inner[side].end());
          }
        }
        const std::vector<glm::vec2> ring = ringOf(lo, hi, inner);
        for (uint32_t diagonal = 0; diagonal < 3; ++diagonal)
          smallest[diagonal] = std::min(smallest[diagonal], checkRing(ring, lo, hi, diagonal));
        ++shapes;
      }
  WARN(shapes << " rings; smallest triangle " << smallest[0] << " of its rectangle (along the "
              << "main diagonal " << smallest[1] << ", the other " << smallest[2] << ")");
  CHECK(shapes == 3 * 625 * 2);
}

TEST_CASE("a ring cut along one diagonal: the four corners, and a corner of it missing",
          "[ring]") {
  const std::vector<glm::vec2> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::vector<std::array<uint32_t, 3>> triangles;
  REQUIRE(triangulateRectangleRingAlong(square, {0, 0}, {1, 1}, 2, triangles));
  REQUIRE(triangles.size() == 2);
  for (const auto& t : triangles)  // both hold the anti-diagonal 1–3, neither 0–2
    CHECK((std::count(t.begin(), t.end(), 1u) == 1 && std::count(t.begin(), t.end(), 3u) == 1));
  // Corner (1, 1) merged away: the main diagonal cannot be kept, the anti-diagonal can.
  const std::vector<glm::vec2> cut = {{0, 0}, {1, 0}, {1, 0.5f}, {0, 1}};
  CHECK_FALSE(triangulateRectangleRingAlong(cut, {0, 0}, {1, 1}, 1, triangles));
  CHECK(triangles.empty());
  CHECK(triangulateRectangleRingAlong(cut, {0, 0}, {1, 1}, 2, triangles));
}

TEST_CASE("a long run of points on one side: 64 on the bottom, none elsewhere", "[ring]") {
  std::array<std::vector<float>, 4> inner;
  for (int i = 1; i < 65; ++i) inner[0].push_back(float(i) / 65.0f);
  checkRing(ringOf({0, 0}, {1, 1}, inner), {0, 0}, {1, 1});
  std::array<std::vector<float>, 4> opposite;
  for (int i = 1; i < 16; ++i) opposite[0].push_back(float(i) / 16.0f);
  for (int i = 1; i < 16; ++i) opposite[2].push_back(float(i) / 16.0f);
  checkRing(ringOf({0, 0}, {1, 1}, opposite), {0, 0}, {1, 1});
  for (uint32_t diagonal : {1u, 2u}) {
    checkRing(ringOf({0, 0}, {1, 1}, inner), {0, 0}, {1, 1}, diagonal);
    checkRing(ringOf({0, 0}, {1, 1}, opposite), {0, 0}, {1, 1}, diagonal);
  }
}

TEST_CASE("one point on a side: its three triangles all use it (shortest new edges first)",
          "[ring]") {
  const std::vector<glm::vec2> ring = {{0, 0}, {0.5f, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::vector<std::array<uint32_t, 3>> triangles;
  REQUIRE(triangulateRectangleRing(ring, {0, 0}, {1, 1}, triangles));
  REQUIRE(triangles.size() == 3);
  for (const auto& t : triangles) CHECK((t[0] == 1 || t[1] == 1 || t[2] == 1));
}

TEST_CASE("rings the triangulator cannot take are refused, not triangulated", "[ring]") {
  std::vector<std::array<uint32_t, 3>> triangles;
  const glm::vec2 lo(0, 0), hi(1, 1);
  // A point inside the rectangle (off every side).
  CHECK_FALSE(triangulateRectangleRing({{0, 0}, {1, 0}, {0.5f, 0.5f}, {0, 1}}, lo, hi, triangles));
  CHECK(triangles.empty());
  // Clockwise.
  CHECK_FALSE(triangulateRectangleRing({{0, 0}, {0, 1}, {1, 1}, {1, 0}}, lo, hi, triangles));
  // A point twice.
  CHECK_FALSE(
      triangulateRectangleRing({{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}}, lo, hi, triangles));
  // All on one side, and too few points.
  CHECK_FALSE(triangulateRectangleRing({{0, 0}, {0.5f, 0}, {1, 0}}, lo, hi, triangles));
  CHECK_FALSE(triangulateRectangleRing({{0, 0}, {1, 0}}, lo, hi, triangles));
  // An empty rectangle.
  CHECK_FALSE(triangulateRectangleRing({{0, 0}, {1, 0}, {1, 0}}, lo, {1, 0}, triangles));
  // Three points on three sides is one triangle.
  REQUIRE(triangulateRectangleRing({{0.5f, 0}, {1, 1}, {0, 0.5f}}, lo, hi, triangles));
  CHECK(triangles.size() == 1);
}

TEST_CASE("a diagonal's halves give what the ring triangulation gives each alone", "[ring]") {
  // triangulateRectangleRingAlong writes the common halves (three corners, or one point more)
  // directly: the same triangles in the same order as triangulateRectangleRing on the half.
  const std::pair<glm::vec2, glm::vec2> rectangles[] = {
      {{0, 0}, {1, 1}}, {{0.25f, 0.5f}, {0.3125f, 0.5078125f}}, {{0.6f, 0.1f}, {0.7f, 0.9f}}};
  const float fractions[] = {1.0f / 64, 0.25f, 0.5f, 0.7f, 63.0f / 64};
  size_t rings = 0;
  for (const auto& [lo, hi] : rectangles)
    for (int counts = 0; counts < 3 * 3 * 3 * 3; ++counts)
      for (float f : fractions) {
        std::array<std::vector<float>, 4> inner;
        for (int side = 0, c = counts; side < 4; ++side, c /= 3)
          for (int i = 0; i < c % 3; ++i) inner[side].push_back(i == 0 ? f : 0.5f * (f + 1));
        const std::vector<glm::vec2> ring = ringOf(lo, hi, inner);
        const size_t n = ring.size();
        for (uint32_t diagonal = 1; diagonal <= 2; ++diagonal) {
          std::vector<std::array<uint32_t, 3>> along;
          REQUIRE(triangulateRectangleRingAlong(ring, lo, hi, diagonal, along));
          // The halves cut at the diagonal's corners, as the function does.
          const glm::vec2 from = diagonal == 1 ? lo : glm::vec2(hi.x, lo.y);
          const glm::vec2 to = diagonal == 1 ? hi : glm::vec2(lo.x, hi.y);
          const size_t a = size_t(std::find(ring.begin(), ring.end(), from) - ring.begin());
          const size_t b = size_t(std::find(ring.begin(), ring.end(), to) - ring.begin());
          std::vector<std::array<uint32_t, 3>> expected;
          for (const auto& [start, end] : {std::pair{a, b}, std::pair{b, a}}) {
            std::vector<glm::vec2> half;
            std::vector<uint32_t> original;
            for (size_t i = start;; i = (i + 1) % n) {
              half.push_back(ring[i]);
              original.push_back(uint32_t(i));
              if (i == end) break;
            }
            std::vector<std::array<uint32_t, 3>> triangles;
            REQUIRE(triangulateRectangleRing(half, lo, hi, triangles));
            for (const auto& t : triangles)
              expected.push_back({original[t[0]], original[t[1]], original[t[2]]});
          }
          CHECK(along == expected);
          ++rings;
        }
      }
  CHECK(rings == 3 * 81 * 5 * 2);
}
