// fp32 (the shader's arithmetic, via its bit-exact mirror) against the double-precision
// reference running the same algorithm. Trees must have the same leaves except below nodes
// whose test value lies within the ambiguity band of its threshold, or whose rectangle moved
// because an ancestor's split point moved (C and D at near-ties of κ); the test prints how
// many nodes were of each kind and fails on any it cannot explain.
#include <catch2/catch.hpp>

#include "eval/evaluator.h"
#include "io/bpt_reader.h"
#include "patch_samples.h"
#include "quadtree/quadtree.h"
#include "sweep_share.h"
#include "tree_divergence.h"

using namespace tessera;

namespace {

// fp32 test values carry errors around 1e-6 (more near degenerate points, where the fp32
// normal switches to its limiting direction at ε = 1e-5): the band is generous on purpose.
constexpr double kAmbiguityBand = 2e-3;

void checkPrecision(const std::vector<BezierPatch>& input, const char* what) {
  auto patches = toGpuPatches(input);
  auto fp32 = makeMirrorClassifier();
  auto fp64 = makeReferenceClassifier();
  for (SplitRule rule : {SplitRule::Midpoint, SplitRule::SampledMax, SplitRule::TrueMax}) {
    // The middle threshold always; all four in Release (sweep_share.h).
    const std::vector<float> thresholds =
        test::sweepShare() == 1.0 ? std::vector<float>{0.3f, 0.2f, 0.1f, 0.05f}
                                  : std::vector<float>{0.1f};
    for (float threshold : thresholds) {
      QuadtreeOptions options;
      options.rule = rule;
      options.linearity = options.flatness = threshold;
      options.maxDepth = 7;
      QuadtreeResult a = buildQuadtree(patches, options, *fp32);
      QuadtreeResult b = buildQuadtree(patches, options, *fp64);
      test::requireExplainedDivergence(a, b, options, kAmbiguityBand, what);
    }
  }
}

}  // namespace

TEST_CASE("fp32 and double quad-trees agree outside the ambiguity band: random patches",
          "[quadtree][precision]") {
  checkPrecision(test::randomBicubicPatches(12, 7), "random patches");
}

TEST_CASE("fp32 and double quad-trees agree outside the ambiguity band: collapsed edges",
          "[quadtree][precision]") {
  checkPrecision(test::collapsedEdgePatches(), "collapsed-edge patches");
}

TEST_CASE("fp32 and double quad-trees agree outside the ambiguity band: the teapot",
          "[quadtree][precision]") {
  checkPrecision(readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt"), "teapot");
}
