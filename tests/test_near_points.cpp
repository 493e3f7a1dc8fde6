// Near-coincident points of two quad-trees on one line (host/mesh/near_points.h): merged by
// their gap relative to the leaf edges that end there, or when fp32 cannot separate them on the
// model, never by a fixed parameter distance.
#include <catch2/catch.hpp>

#include <algorithm>

#include "mesh/near_points.h"

using namespace tessera;

namespace {

const auto kAlwaysDistinct = [](float, float) { return true; };

}  // namespace

TEST_CASE("near points merge relative to the leaf edges that end there", "[watertight]") {
  // One tree's corners at 0, 0.5, 1 (edges 0.5); the other's at 0.25, 0.5 + g, 0.75 (edges
  // 0.25). The pair (0.5, 0.5 + g) is one point when g ≤ 0.25 / 256.
  for (float scale : {1.0f, 1e-3f}) {
    const auto pairsFor = [&](float gap) {
      std::vector<LinePoint> points = {{0.0f, 0.5f}, {0.5f * scale, 0.5f * scale},
                                       {1.0f * scale, 0.5f * scale}, {0.25f * scale, 0.25f * scale},
                                       {(0.5f + gap) * scale, 0.25f * scale},
                                       {0.75f * scale, 0.25f * scale}};
      return nearPairs(points, kAlwaysDistinct);
    };
    INFO("leaf edges scaled by " << scale);
    // The same ratio merges at any scale: no fixed distance.
    const std::vector<std::pair<float, float>> merged = pairsFor(0.9f * 0.25f / 256.0f);
    REQUIRE(merged.size() == 1);
    REQUIRE(merged[0].first == 0.5f * scale);
    REQUIRE(pairsFor(1.1f * 0.25f / 256.0f).empty());
  }
  // A teacup-like pair 1.14e-6 apart between leaf edges of 1/64: merged (a fixed 1e-6 did not).
  std::vector<LinePoint> teacup = {{0.34375f, 1.0f / 64}, {0.34375114f, 1.0f / 64}};
  REQUIRE(nearPairs(teacup, kAlwaysDistinct).size() == 1);
}

TEST_CASE("near points merge when fp32 cannot tell them apart", "[watertight]") {
  // Leaf edges of 1e-5 and a gap of 1e-7 (ratio 1/100: kept apart by the ratio alone).
  std::vector<LinePoint> points = {{0.5f, 1e-5f}, {0.5f + 1e-7f, 1e-5f}};
  bool asked = false;
  REQUIRE(nearPairs(points, [&](float, float) { return asked = true; }).empty());
  REQUIRE(asked);
  REQUIRE(nearPairs(points, [](float, float) { return false; }).size() == 1);
  // Points a whole leaf edge apart are one tree's own corners: never asked, never merged.
  std::vector<LinePoint> apart = {{0.5f, 1e-5f}, {0.5f + 1e-5f, 1e-5f}};
  asked = false;
  REQUIRE(nearPairs(apart, [&](float, float) { return asked = true, false; }).empty());
  REQUIRE_FALSE(asked);
}

TEST_CASE("near points: equal points fold into one with the shorter edge", "[watertight]") {
  std::vector<LinePoint> points = {{0.5f, 0.5f}, {0.25f, 0.25f}, {0.5f, 0.125f}, {0.75f, 0.25f}};
  nearPairs(points, kAlwaysDistinct);
  REQUIRE(points.size() == 3);
  REQUIRE(points[1].t == 0.5f);
  REQUIRE(points[1].spacing == 0.125f);
}

TEST_CASE("near points: the order a line's points come in does not matter", "[watertight]") {
  // The triangulator lists a line's points leaf by leaf, in whatever order its lookups go
  // (line_points.cpp, collectLinePoints): the points kept and the pairs found must not
  // depend on it, equal t with different spacings included.
  const std::vector<LinePoint> listed = {{0.5f, 0.5f},   {0.25f, 0.25f},         {0.5f, 0.125f},
                                         {0.75f, 0.25f}, {0.5f + 1e-4f, 0.125f}, {0.25f, 0.0625f},
                                         {0.0f, 0.25f},  {1.0f, 0.25f}};
  std::vector<LinePoint> points = listed;
  const std::vector<std::pair<float, float>> pairs = nearPairs(points, kAlwaysDistinct);
  REQUIRE(pairs.size() == 1);  // (0.5, 0.5 + 1e-4): 1e-4 ≤ 0.125 / 256
  std::vector<size_t> order(listed.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  for (int shuffle = 0; shuffle < 40; ++shuffle) {
    // A fixed sequence of permutations: rotate, then swap two by a stride.
    std::rotate(order.begin(), order.begin() + 3, order.end());
    std::swap(order[size_t(shuffle) % order.size()], order[size_t(shuffle * 5 + 1) % order.size()]);
    std::vector<LinePoint> permuted;
    for (size_t k : order) permuted.push_back(listed[k]);
    INFO("permutation " << shuffle);
    REQUIRE(nearPairs(permuted, kAlwaysDistinct) == pairs);
    REQUIRE(permuted.size() == points.size());
    for (size_t k = 0; k < points.size(); ++k) {
      REQUIRE(permuted[k].t == points[k].t);
      REQUIRE(permuted[k].spacing == points[k].spacing);
    }
  }
}
