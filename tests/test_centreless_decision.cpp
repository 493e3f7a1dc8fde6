// The mirror's shortcut in rule T's decision for terms without centres (C = 0, the revolution
// bound's: mirror::toleranceDecisionOf) gives the same bits as the shared text without it.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "common/glsl_builtins.h"
#include "quadtree/detail/classify_mirror.h"

namespace tessera::mirror::glsl {
namespace {  // this file's own copy, compiled without the shortcut
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include "shaders/lib/shared_glsl_cpp.h"
#include "shaders/lib/tolerance_bound.h"  // without TOLERANCE_DECISION_CENTRELESS_SHORTCUT
#pragma GCC diagnostic pop
}  // namespace
}  // namespace tessera::mirror::glsl

namespace {

bool sameBits(const tessera::gpu::NodeDecision& a, const tessera::gpu::NodeDecision& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

}  // namespace

TEST_CASE("rule T: the centreless decision's shortcut gives the full text's bits",
          "[tolerance][revolution]") {
  using namespace tessera;
  std::mt19937 random(41);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const float specials[] = {0.0f, -0.0f, 1e-30f, 1e30f, std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::quiet_NaN()};
  size_t compared = 0, mismatched = 0, leaves = 0, grids = 0;
  for (int k = 0; k < 20000; ++k) {
    // Terms spanning 12 decades around δ, some zero or special (unbounded nodes, flat rows).
    const auto term = [&]() {
      if (random() % 16 == 0) return specials[random() % 6];
      return std::ldexp(unit(random), int(random() % 40) - 30);
    };
    const gpu::vec4 bounds(term(), 0.0f, term(), std::ldexp(unit(random), -40));
    gpu::QuadNode node{};
    const float u0 = 0.5f * unit(random), v0 = 0.5f * unit(random);
    node.rect = gpu::vec4(u0, v0, u0 + std::ldexp(1.0f, -int(random() % 20)),
                          v0 + std::ldexp(1.0f, -int(random() % 20)));
    node.level = random() % 34;
    gpu::ClassifyPush params{};
    params.minSize = random() % 4 == 0 ? 1e-3f : 0.0f;
    params.maxDepth = 32;
    params.tolerance = std::ldexp(1.0f, -int(random() % 20));
    params.toleranceSplitCap = 1 + random() % 4;
    const gpu::NodeDecision fast = mirror::toleranceDecisionOf(bounds, node, params);
    const gpu::NodeDecision full = mirror::glsl::toleranceDecision(
        mirror::glsl::toleranceTermsOf(bounds), node, params);
    ++compared;
    if (!sameBits(fast, full)) ++mismatched;
    leaves += fast.cause == gpu::kCauseWithinTolerance;
    grids += fast.cause == gpu::kCauseSplitGrid;
  }
  CHECK(mismatched == 0);
  CHECK(compared == 20000);
  // Both kinds of answer met (not every node a leaf or every node split).
  CHECK(leaves > 1000);
  CHECK(grids > 1000);
}
