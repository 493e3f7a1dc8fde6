// Rule T's mirror for general patches compiled once per degree pair
// (host/eval/detail/general_tolerance_variants.h, with the SSE class maxima of
// division_class_maxima_sse.inc): each variant's decisions equal the generic mirror's bit for
// bit, on nodes of every size, for polynomial nets and for rational ones with positive,
// negative and vanishing weights.
#include <catch2/catch.hpp>

#include <cstring>
#include <random>

#include "eval/detail/general_tolerance_variants.h"
#include "eval/general_mirror.h"
#include "eval/patch_set.h"
#include "general_samples.h"
#include "quadtree/quadtree.h"

using namespace tessera;

namespace {

bool sameBits(const gpu::NodeDecision& a, const gpu::NodeDecision& b) {
  static_assert(sizeof(gpu::NodeDecision) == 8 * sizeof(uint32_t), "no padding");
  uint32_t x[8], y[8];
  std::memcpy(x, &a, sizeof x);
  std::memcpy(y, &b, sizeof y);
  return std::memcmp(x, y, sizeof x) == 0;
}

// The whole domain, its quadrants, and random rectangles down to 2⁻¹² wide.
std::vector<gpu::vec4> testRects(uint32_t seed) {
  std::vector<gpu::vec4> rects = {{0, 0, 1, 1},     {0, 0, 0.5f, 0.5f}, {0.5f, 0, 1, 0.5f},
                                  {0, 0.5f, 0.5f, 1}, {0.5f, 0.5f, 1, 1}};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::uniform_int_distribution<int> level(1, 12);
  for (int k = 0; k < 24; ++k) {
    const float wu = std::ldexp(1.0f, -level(rng)), wv = std::ldexp(1.0f, -level(rng));
    const float u0 = std::floor(unit(rng) * (1.0f / wu)) * wu;
    const float v0 = std::floor(unit(rng) * (1.0f / wv)) * wv;
    rects.push_back({u0, v0, std::min(1.0f, u0 + wu), std::min(1.0f, v0 + wv)});
  }
  return rects;
}

}  // namespace

TEST_CASE("rule T mirror: each degree pair's variant decides as the generic mirror, bit for bit",
          "[tolerance][parity]") {
  struct Pair {
    int n, m;
    bool rational;
  };
  const Pair pairs[] = {{1, 1, false}, {1, 2, false}, {1, 3, false}, {2, 1, false}, {2, 2, false},
                        {2, 3, false}, {3, 1, false}, {3, 2, false}, {3, 3, false}, {2, 1, true},
                        {1, 2, true},  {2, 2, true},  {3, 3, true}};
  uint32_t seed = 1700;
  size_t compared = 0;
  for (const Pair& pair : pairs) {
    std::vector<BezierPatch> patches =
        test::randomGeneralPatches(3, pair.n, pair.m, pair.rational, false, ++seed);
    // A rational 2 × 1 beside polynomial 3 × 3 patches: a general set, not a bicubic one.
    if (!pair.rational)
      for (BezierPatch& p : test::randomGeneralPatches(1, 2, 1, true, false, ++seed))
        patches.push_back(p);
    if (pair.rational) {
      // The same surface with every weight negated, one weight of the other sign, and (2 × 2,
      // 3 × 3: an inner point) a vanishing weight, which leaves the SSE class maxima for the
      // scalar.
      BezierPatch negated = patches[0], mixed = patches[1];
      for (double& w : negated.weights) w = -w;
      mixed.weights[1] = -mixed.weights[1];
      patches.push_back(negated);
      patches.push_back(mixed);
      if (pair.n == pair.m && pair.n >= 2)
        for (BezierPatch& p : test::randomGeneralPatches(2, pair.n, pair.m, true, true, ++seed))
          patches.push_back(p);
    }
    const PatchSet set = toPatchSet(patches);
    const GeneralPatchSet& general = set.general();
    for (size_t p = 0; p < general.patches.size(); ++p) {
      const gpu::GeneralPatch& patch = general.patches[p];
      const mirror::GeneralToleranceClassify variant = mirror::generalToleranceVariant(patch);
      REQUIRE(variant != nullptr);
      for (double tolerance : {1e-2, 1e-4, 1e-6}) {
        QuadtreeOptions options = toleranceOptions(tolerance);
        const gpu::ClassifyPush params = classifyParams(options, 1);
        for (const gpu::vec4& rect : testRects(seed + uint32_t(p))) {
          const gpu::QuadNode node{rect, uint32_t(p), 3, 0, 0};
          const gpu::NodeDecision generic = mirror::classifyGeneralNodeGeneric(
              patch, general.points.data(), node, gpu::kSplitRuleTolerance, 0, params);
          const gpu::NodeDecision fixed = variant(patch, general.points.data(), node, params);
          INFO("degree " << pair.n << " x " << pair.m << (pair.rational ? " rational" : "")
                         << ", patch " << p << ", rect " << rect.x << " " << rect.y << " "
                         << rect.z << " " << rect.w << ", tolerance " << tolerance);
          REQUIRE(sameBits(generic, fixed));
          ++compared;
        }
      }
    }
  }
  CHECK(compared > 3000);
}

TEST_CASE("rule T mirror: only the variants' degree pairs have one", "[tolerance]") {
  gpu::GeneralPatch patch{5, 3, 0, 0};
  CHECK(mirror::generalToleranceVariant(patch) == nullptr);
  patch = {3, 2, 1, 0};  // rational 3 × 2: the generic mirror
  CHECK(mirror::generalToleranceVariant(patch) == nullptr);
  patch = {1, 1, 1, 0};
  CHECK(mirror::generalToleranceVariant(patch) == nullptr);
  patch = {3, 1, 0, 0};
  CHECK(mirror::generalToleranceVariant(patch) == &mirror::generalTolerance_p3x1);
  patch = {2, 2, 1, 0};
  CHECK(mirror::generalToleranceVariant(patch) == &mirror::generalTolerance_r2x2);
  patch = {3, 3, 1, 0};  // rule T's screen-space patches (host/mesh/screen_tolerance.cpp)
  CHECK(mirror::generalToleranceVariant(patch) == &mirror::generalTolerance_r3x3);
}
