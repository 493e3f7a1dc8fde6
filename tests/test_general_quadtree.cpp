// Quad-trees of general patches (degree 1..7, rational; quadtree_general.comp.glsl):
// - GPU trees equal the fp32 mirror's bit for bit on lavapipe (same leaves, rectangles, split
//   points and test values) for degree 2×2, 5×4 and rational patches with inner zero weights,
//   rules B, C, D at thresholds 0.3, 0.1, 0.05 (maximum depth 5; 0.1 alone under the
//   sanitizers);
// - fp32 trees agree with the double reference (rational.h, bezier.h) outside the ambiguity
//   band of test_quadtree_precision.cpp, and every divergence is explained.
#include <catch2/catch.hpp>

#include <sstream>

#include "general_samples.h"
#include "gpu_test_context.h"
#include "quadtree/quadtree.h"
#include "quadtree_compare.h"
#include "sweep_share.h"
#include "tree_divergence.h"

using namespace tessera;

namespace {

constexpr double kAmbiguityBand = 2e-3;  // as test_quadtree_precision.cpp

QuadtreeOptions optionsFor(SplitRule rule, float threshold) {
  QuadtreeOptions o;
  o.rule = rule;
  o.linearity = o.flatness = threshold;
  o.maxDepth = 5;  // keeps each case within a few seconds on lavapipe's 2 cores
  return o;
}

// One classifier for every input: llvmpipe compiles the general classifier once per rule
// (about 13 s for rule D, whose κ evaluations are all inlined; the on-disk pipeline cache
// makes that a first-run cost: this case takes ~30 s cold, ~6 s warm).
void checkGpuTrees(NodeClassifier& gpu, const std::vector<BezierPatch>& input,
                   const char* what) {
  test::gpuContext();  // the device comes up (or the test fails loudly) before any tree
  GeneralPatchSet set = toGeneralPatchSet(input);
  auto cpu = makeMirrorClassifier();
  size_t leaves = 0;
  // The middle threshold always; all three in Release (sweep_share.h: the sanitizers look at
  // the host's paths, which every threshold takes).
  const std::vector<float> thresholds = test::sweepShare() == 1.0
                                            ? std::vector<float>{0.3f, 0.1f, 0.05f}
                                            : std::vector<float>{0.1f};
  std::ostringstream thresholdList;
  for (size_t k = 0; k < thresholds.size(); ++k) thresholdList << (k ? ", " : "") << thresholds[k];
  for (SplitRule rule : {SplitRule::Midpoint, SplitRule::SampledMax, SplitRule::TrueMax})
    for (float threshold : thresholds) {
      QuadtreeOptions o = optionsFor(rule, threshold);
      QuadtreeResult a = buildQuadtree(set, o, gpu);
      QuadtreeResult b = buildQuadtree(set, o, *cpu);
      const bool identical = test::identicalTrees(a, b);
      leaves += a.leaves.size();
      INFO(what << " rule " << splitRuleLetter(rule) << " threshold " << threshold << ": GPU "
                << a.leaves.size() << " leaves depth " << a.depth << ", mirror "
                << b.leaves.size() << " leaves depth " << b.depth);
      if (test::exactMirrorArithmetic())
        REQUIRE(identical);
      else  // every differing node explained by the ambiguity band (tree_divergence.h)
        test::requireExplainedDivergence(a, b, o, kAmbiguityBand, what, "GPU", "mirror");
    }
  WARN(what << ": GPU and mirror trees identical for B, C, D at " << thresholdList.str() << " ("
            << leaves << " leaves in all)");
  test::requireValidationClean();
}

void checkPrecision(const std::vector<BezierPatch>& input, const char* what) {
  GeneralPatchSet set = toGeneralPatchSet(input);
  auto fp32 = makeMirrorClassifier();
  auto fp64 = makeReferenceClassifier();
  for (SplitRule rule : {SplitRule::Midpoint, SplitRule::SampledMax, SplitRule::TrueMax})
    // The middle threshold always; all three in Release (sweep_share.h).
    for (float threshold : test::sweepShare() == 1.0 ? std::vector<float>{0.3f, 0.1f, 0.05f}
                                                     : std::vector<float>{0.1f}) {
      QuadtreeOptions o = optionsFor(rule, threshold);
      QuadtreeResult a = buildQuadtree(set, o, *fp32);
      QuadtreeResult b = buildQuadtree(set, o, *fp64);
      test::requireExplainedDivergence(a, b, o, kAmbiguityBand, what);
    }
}

}  // namespace

TEST_CASE("general GPU quad-trees equal the fp32 mirror's: degree 2×2, 5×4, rational",
          "[gpu][quadtree][parity][general]") {
  auto gpu = makeVulkanClassifier(test::gpuContext());
  checkGpuTrees(*gpu, test::randomGeneralPatches(4, 2, 2, false, false, 41), "degree 2x2");
  checkGpuTrees(*gpu, test::randomGeneralPatches(2, 5, 4, false, false, 42), "degree 5x4");
  checkGpuTrees(*gpu, test::randomGeneralPatches(2, 3, 3, true, true, 43), "rational 3x3, inner w=0");
  checkGpuTrees(*gpu, {test::rationalSphere(1.0)[0]}, "rational sphere patch (collapsed side)");
}

TEST_CASE("general fp32 and double quad-trees agree outside the ambiguity band",
          "[quadtree][precision][general]") {
  checkPrecision(test::randomGeneralPatches(2, 5, 4, false, false, 51), "degree 5x4");
  checkPrecision(test::randomGeneralPatches(2, 4, 3, true, true, 52), "rational 4x3, inner w=0");
  checkPrecision({test::rationalSphere(1.0)[0]}, "rational sphere patch (collapsed side)");
}
