#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "trim/detail/open_edges.h"

using tessera::trim_detail::appendReversedOpenEdges;
using tessera::trim_detail::FaceTriangle;

namespace {

// The definition, as the mesher computed it before: the distinct directed edges sorted, each
// whose reverse is absent given reversed.
std::vector<std::pair<uint32_t, uint32_t>> openEdgesBySorting(
    const std::vector<FaceTriangle>& triangles) {
  std::vector<std::pair<uint32_t, uint32_t>> directed, open;
  for (const FaceTriangle& t : triangles)
    for (int k = 0; k < 3; ++k) directed.push_back({t.v[k], t.v[(k + 1) % 3]});
  std::sort(directed.begin(), directed.end());
  directed.erase(std::unique(directed.begin(), directed.end()), directed.end());
  for (const auto& [a, b] : directed)
    if (!std::binary_search(directed.begin(), directed.end(), std::make_pair(b, a)))
      open.push_back({b, a});
  return open;
}

}  // namespace

TEST_CASE("open edges: a grid with holes, repeats and a flipped triangle, as by sorting",
          "[trim]") {
  // A 12 x 12 grid of vertices, two triangles a cell, some cells dropped (holes and a ragged
  // border), one triangle listed twice and one reversed: every kind of edge the cut meets.
  constexpr uint32_t side = 12;
  std::mt19937 random(41);
  std::vector<FaceTriangle> triangles;
  for (uint32_t y = 0; y + 1 < side; ++y)
    for (uint32_t x = 0; x + 1 < side; ++x) {
      if (random() % 5 == 0) continue;
      const uint32_t a = y * side + x, b = a + 1, c = a + side, d = c + 1;
      triangles.push_back({{a, b, d}, false});
      triangles.push_back({{a, d, c}, false});
    }
  triangles.push_back(triangles[17]);
  std::swap(triangles[40].v[1], triangles[40].v[2]);
  std::shuffle(triangles.begin(), triangles.end(), random);

  std::vector<std::pair<uint32_t, uint32_t>> open = {{999, 998}};  // appended after
  appendReversedOpenEdges(triangles, side * side + 3, open);  // unused vertices too
  std::vector<std::pair<uint32_t, uint32_t>> expected = {{999, 998}};
  for (const auto& e : openEdgesBySorting(triangles)) expected.push_back(e);
  REQUIRE(expected.size() > 40);
  CHECK(open == expected);

  std::vector<std::pair<uint32_t, uint32_t>> none;
  appendReversedOpenEdges({}, 5, none);
  CHECK(none.empty());
}
