// How a classified node divides (host/quadtree/node_split.h): rule T's k_u × k_v equal
// children tile the parent exactly, siblings share their lines bit for bit, the outer lines are
// the parent's own (so a neighbour's corners land on them), and two-way splits keep the
// classifier's split point (rules B–D unchanged).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "quadtree/node_split.h"

using namespace tessera;

namespace {

gpu::NodeDecision gridDecision(uint32_t ku, uint32_t kv) {
  gpu::NodeDecision d{};
  d.cause = gpu::kCauseSplitGrid;
  d.pad = ku | (kv << 8);
  return d;
}

}  // namespace

TEST_CASE("node split: grid children tile the parent with shared lines", "[quadtree][tolerance]") {
  std::mt19937 rng(77);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  size_t checked = 0;
  for (int trial = 0; trial < 200; ++trial) {
    float a = unit(rng), b = unit(rng), c = unit(rng), e = unit(rng);
    const gpu::QuadNode node{gpu::vec4(std::min(a, b), std::min(c, e), std::max(a, b),
                                       std::max(c, e)),
                             3, 5, 0, 0};
    if (!(node.rect.x < node.rect.z && node.rect.y < node.rect.w)) continue;
    const uint32_t ku = 1 + trial % 16, kv = 1 + (trial / 16) % 16;
    if (ku * kv < 2) continue;
    const gpu::NodeDecision d = gridDecision(ku, kv);
    const SplitCounts counts = splitCounts(d);
    REQUIRE(counts.u == ku);
    REQUIRE(counts.v == kv);
    std::vector<gpu::QuadNode> kids;
    REQUIRE(appendChildren(node, d, counts, kids));
    REQUIRE(kids.size() == size_t(ku) * kv);
    double area = 0;
    for (uint32_t j = 0; j < kv; ++j)
      for (uint32_t i = 0; i < ku; ++i) {
        const gpu::QuadNode& k = kids[j * ku + i];
        INFO("grid " << ku << "x" << kv << " child " << i << "," << j);
        REQUIRE(k.level == node.level + 1);
        REQUIRE(k.patchIndex == node.patchIndex);
        REQUIRE(k.rect.x < k.rect.z);
        REQUIRE(k.rect.y < k.rect.w);
        // The outer lines are the parent's, bit for bit; inner ones shared with the sibling.
        if (i == 0) REQUIRE(k.rect.x == node.rect.x);
        if (i + 1 == ku) REQUIRE(k.rect.z == node.rect.z);
        if (j == 0) REQUIRE(k.rect.y == node.rect.y);
        if (j + 1 == kv) REQUIRE(k.rect.w == node.rect.w);
        if (i > 0) REQUIRE(k.rect.x == kids[j * ku + i - 1].rect.z);
        if (j > 0) REQUIRE(k.rect.y == kids[(j - 1) * ku + i].rect.w);
        REQUIRE(k.rect.x == equalSplitLine(node.rect.x, node.rect.z, i, ku));
        area += double(k.rect.z - k.rect.x) * double(k.rect.w - k.rect.y);
      }
    const double parent = double(node.rect.z - node.rect.x) * double(node.rect.w - node.rect.y);
    REQUIRE(std::abs(area - parent) <= 1e-6 * parent);
    ++checked;
  }
  WARN(checked << " random nodes split into 2..256 equal children");
  REQUIRE(checked > 150);
}

TEST_CASE("node split: two-way splits cut at the split point; fp32's end is a leaf",
          "[quadtree][tolerance]") {
  gpu::NodeDecision d{};
  d.cause = gpu::kCauseSplit;
  d.split = gpu::vec4(0.3f, 0.6f, 0.0f, 0.0f);
  const gpu::QuadNode node{gpu::vec4(0.0f, 0.5f, 0.5f, 1.0f), 0, 1, 0, 0};
  std::vector<gpu::QuadNode> kids;
  REQUIRE(appendChildren(node, d, splitCounts(d), kids));
  REQUIRE(kids.size() == 4);  // the paper's quadrant order: u-low v-low, u-high, v-high, both
  CHECK(kids[0].rect.z == 0.3f);
  CHECK(kids[1].rect.x == 0.3f);
  CHECK(kids[2].rect.y == 0.6f);
  CHECK(kids[3].rect.x == 0.3f);
  CHECK(kids[3].rect.y == 0.6f);
  d.cause = gpu::kCauseSplitV;
  kids.clear();
  REQUIRE(appendChildren(node, d, splitCounts(d), kids));
  REQUIRE(kids.size() == 2);
  CHECK(kids[1].rect.y == 0.6f);
  CHECK(kids[1].rect.x == 0.0f);
  CHECK(kids[1].rect.z == 0.5f);
  // A node one ulp wide cannot take 3 equal parts: nothing is appended.
  const float lo = 0.5f, hi = std::nextafter(0.5f, 1.0f);
  const gpu::QuadNode thin{gpu::vec4(lo, 0.0f, hi, 1.0f), 0, 20, 0, 0};
  kids.clear();
  CHECK_FALSE(appendChildren(thin, gridDecision(3, 1), {3, 1}, kids));
  CHECK(kids.empty());
  // Codes: ⌈log₂ k⌉ bits a direction.
  CHECK(pathCodeBits(1) == 0);
  CHECK(pathCodeBits(2) == 1);
  CHECK(pathCodeBits(3) == 2);
  CHECK(pathCodeBits(16) == 4);
  // Counts the classifier cannot have meant are an error, not a silent leaf.
  CHECK_THROWS_AS(splitCounts(gridDecision(17, 1)), std::logic_error);
  CHECK_THROWS_AS(splitCounts(gridDecision(1, 1)), std::logic_error);
  gpu::NodeDecision leaf{};
  leaf.cause = gpu::kCauseWithinTolerance;
  CHECK_FALSE(splitCounts(leaf).splits());
}
