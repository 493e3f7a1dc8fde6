// The mesh clean-up steps (mesh/mesh_cleanup.h) on hand-made and random index lists: back-to-back
// pairs against the plain rule they implement, welding of bit-identical positions.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <vector>

#include "mesh/mesh_cleanup.h"

using namespace tessera;

namespace {

// The rule, written plainly: in triangle order, a triangle cancels with the latest open one
// whose corners, rotated to start at the smallest, are its own reversed (b and c swapped);
// otherwise it stays open.
std::vector<bool> backToBackByRule(const std::vector<uint32_t>& indices) {
  using Key = std::array<uint32_t, 3>;
  const auto keyOf = [&](size_t t, bool reversed) {
    Key k = {indices[3 * t], indices[3 * t + 1], indices[3 * t + 2]};
    if (reversed) std::swap(k[1], k[2]);
    std::rotate(k.begin(), std::min_element(k.begin(), k.end()), k.end());
    return k;
  };
  std::map<Key, std::vector<size_t>> open;
  std::vector<bool> cancelled(indices.size() / 3, false);
  for (size_t t = 0; t < cancelled.size(); ++t) {
    std::vector<size_t>& reverse = open[keyOf(t, true)];
    if (!reverse.empty()) {
      cancelled[reverse.back()] = cancelled[t] = true;
      reverse.pop_back();
      continue;
    }
    open[keyOf(t, false)].push_back(t);
  }
  return cancelled;
}

// `count` triangles, each one of `base` picked at random, maybe reversed, then rotated: pairs of
// a triangle and its reverse meet in the buckets of their smallest corner.
std::vector<uint32_t> drawnFrom(const std::vector<std::array<uint32_t, 3>>& base, int count,
                                std::mt19937& random) {
  std::uniform_int_distribution<size_t> pick(0, base.size() - 1);
  std::vector<uint32_t> indices;
  for (int t = 0; t < count; ++t) {
    std::array<uint32_t, 3> c = base[pick(random)];
    if (random() % 2) std::swap(c[1], c[2]);
    std::rotate(c.begin(), c.begin() + random() % 3, c.end());
    indices.insert(indices.end(), c.begin(), c.end());
  }
  return indices;
}

}  // namespace

TEST_CASE("mesh cleanup: back-to-back pairs cancel, latest first", "[mesh][cleanup]") {
  // 0: (0 1 2); 1: its reverse, cancels 0; 2, 3: (0 1 2) twice, rotated; 4: a reverse, cancels
  // the latest (3); 5: a degenerate (5 5 6) and 6: (5 6 5), which the rotation calls its
  // reverse; 7: an unrelated triangle.
  const std::vector<uint32_t> indices = {0, 1, 2, 0, 2, 1, 1, 2, 0, 2, 0, 1, 2, 1, 0,
                                         5, 5, 6, 5, 6, 5, 7, 8, 9};
  const std::vector<bool> expected = {true, true, false, true, true, true, true, false};
  REQUIRE(backToBackPairs(indices) == expected);
  REQUIRE(backToBackByRule(indices) == expected);
  REQUIRE(backToBackPairs({}).empty());
}

TEST_CASE("mesh cleanup: back-to-back pairs follow the rule on random meshes", "[mesh][cleanup]") {
  std::mt19937 random(20261127);
  for (uint32_t vertices : {3u, 4u, 6u, 40u}) {
    std::uniform_int_distribution<uint32_t> corner(0, vertices - 1);
    std::vector<uint32_t> indices(3 * 2000);
    for (uint32_t& i : indices) i = corner(random);
    const std::vector<bool> fast = backToBackPairs(indices), rule = backToBackByRule(indices);
    INFO(vertices << " vertices: " << std::count(rule.begin(), rule.end(), true) << " cancelled");
    REQUIRE(fast == rule);
    REQUIRE(std::count(rule.begin(), rule.end(), true) > 0);
  }
}

TEST_CASE("mesh cleanup: back-to-back pairs follow the rule where vertices have few triangles",
          "[mesh][cleanup]") {
  // Many vertices, few triangles each (as in a real mesh): each triangle is one of 300 random
  // ones, rotated and maybe reversed, so pairs meet in buckets of a handful.
  std::mt19937 random(20261128);
  std::uniform_int_distribution<uint32_t> corner(0, 9999);
  std::vector<std::array<uint32_t, 3>> base(300);
  for (auto& b : base) b = {corner(random), corner(random), corner(random)};
  // 140,000 triangles are past the 2¹⁷ whose bit table and slots a thread keeps
  // (back_to_back.cpp): their slots are hashed again.
  for (const int count : {3000, 140000}) {
    const std::vector<uint32_t> indices = drawnFrom(base, count, random);
    const std::vector<bool> fast = backToBackPairs(indices), rule = backToBackByRule(indices);
    INFO(count << " triangles");
    REQUIRE(fast == rule);
    REQUIRE(std::count(rule.begin(), rule.end(), true) > 1000);
  }
}

TEST_CASE("mesh cleanup: back-to-back pairs are the same on any thread count",
          "[mesh][cleanup][threads]") {
  // Enough triangles (30,000) for the buckets to be settled on several threads: each one of
  // 3,000 random ones, rotated and maybe reversed; a tenth of those share one of four hub
  // vertices, whose buckets (hundreds of triangles) take the map path.
  std::mt19937 random(20261130);
  std::uniform_int_distribution<uint32_t> corner(4, 49999), hub(0, 3);
  std::vector<std::array<uint32_t, 3>> base(3000);
  for (size_t k = 0; k < base.size(); ++k)
    base[k] = {k % 10 == 0 ? hub(random) : corner(random), corner(random), corner(random)};
  const std::vector<uint32_t> indices = drawnFrom(base, 30000, random);
  const std::vector<bool> rule = backToBackByRule(indices);
  REQUIRE(std::count(rule.begin(), rule.end(), true) > 10000);
  std::vector<uint32_t> ruleList;  // the same triangles as indices (backToBackTriangles)
  for (size_t t = 0; t < rule.size(); ++t)
    if (rule[t]) ruleList.push_back(uint32_t(t));
  for (unsigned threads : {1u, 2u, 3u, 0u}) {
    INFO(threads << " threads");
    REQUIRE(backToBackPairs(indices, threads) == rule);
    REQUIRE(backToBackTriangles(indices, threads) == ruleList);
  }
}

TEST_CASE("mesh cleanup: welding keeps each position's first vertex, on any thread count",
          "[mesh][cleanup][threads]") {
  // Positions drawn from a few hundred, -0 and +0 the same point: the plain rule is a map from
  // a position to the first vertex there.
  std::mt19937 random(20261129);
  std::uniform_int_distribution<int> pick(0, 299), sign(0, 1);
  // 20,000 and then 5,000 take the flat table (its room kept from the larger), 140,000 (past
  // 2¹⁷) the sharded map (position_weld.cpp).
  const size_t count = GENERATE(size_t(20000), size_t(5000), size_t(140000));
  std::vector<glm::vec3> positions(count);
  for (glm::vec3& p : positions) {
    const int k = pick(random);
    p = glm::vec3(float(k % 7) * 0.25f, float(k / 7 % 5), float(k / 35));
    if (p.x == 0.0f && sign(random)) p.x = -0.0f;
  }
  std::map<std::array<float, 3>, uint32_t> first;
  std::vector<uint32_t> expected;
  for (uint32_t i = 0; i < positions.size(); ++i) {
    const glm::vec3& p = positions[i];
    expected.push_back(first.try_emplace({p.x + 0.0f, p.y, p.z}, i).first->second);
  }
  REQUIRE(first.size() == 300);
  for (unsigned threads : {1u, 2u, 3u, 0u}) {
    INFO(count << " positions, " << threads << " threads");
    REQUIRE(weldIdenticalPositions(positions, threads) == expected);
  }
}
