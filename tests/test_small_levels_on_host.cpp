// The Vulkan backend's classifier decides batches of fewer than kHostLevelNodes nodes on the
// host with the fp32 mirror (withSmallLevelsOnHost): its trees must be the all-device trees
// (bit for bit where the device rounds as the mirror does), its small rule T levels must
// really be the host's and its large ones (and every level of rule B, as of C and D) the
// device's, and a tree of small levels alone never needs the device. (Rule D's pipeline alone
// would cost the test half a second of lavapipe's compile: rule B stands for the rules the
// device keeps.)
#include <catch2/catch.hpp>

#include "eval/patch_set.h"
#include "gpu_test_context.h"
#include "io/bpt_reader.h"
#include "quadtree/quadtree.h"
#include "quadtree_compare.h"

using namespace tessera;

namespace {

QuadtreeOptions optionsFor(SplitRule rule) {
  if (rule == SplitRule::Tolerance) return toleranceOptions(0.02);  // the teapot's units
  QuadtreeOptions options;
  options.rule = rule;
  options.maxDepth = 8;
  return options;
}

// A classifier standing in for a device that must not be asked: a tree of small levels only.
class RefusingClassifier final : public NodeClassifier {
 public:
  std::string name() const override { return "refusing"; }
  void beginTree(const PatchSet&) override { FAIL("the device got the patches"); }
  void classify(const PatchSet&, const std::vector<gpu::QuadNode>&, const QuadtreeOptions&,
                std::vector<gpu::NodeDecision>&, LevelStats&) override {
    FAIL("the device got a batch");
  }
};

}  // namespace

TEST_CASE("small levels on the host: the all-device tree, small levels the mirror's",
          "[gpu][quadtree][tolerance][parity]") {
  vk::Context& context = test::gpuContext();
  const PatchSet teapot = toPatchSet(readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt"));
  auto device = withSmallLevelsOnHost(makeVulkanClassifier(context), 0);
  auto hybrid = withSmallLevelsOnHost(makeVulkanClassifier(context));
  for (SplitRule rule : {SplitRule::Midpoint, SplitRule::Tolerance}) {
    QuadtreeOptions options = optionsFor(rule);
    options.timeGpu = true;
    const QuadtreeResult a = buildQuadtree(teapot, options, *device);
    const QuadtreeResult b = buildQuadtree(teapot, options, *hybrid);
    INFO("rule " << splitRuleLetter(rule) << ": device " << a.leaves.size() << " leaves, hybrid "
                 << b.leaves.size());
    if (test::exactMirrorArithmetic()) {
      REQUIRE(test::identicalTrees(a, b));
    } else {
      REQUIRE(double(a.leaves.size()) == Approx(double(b.leaves.size())).epsilon(0.02));
    }
    for (const LevelStats& level : a.levels) CHECK(level.hostNodes == 0);
    // Every level here is one batch: under rule T on the host whole when small, else on the
    // device whole; rule B keeps every level on the device.
    const bool hostRule = rule == SplitRule::Tolerance;
    size_t hostLevels = 0, deviceLevels = 0;
    for (const LevelStats& level : b.levels) {
      INFO("level " << level.level << ": " << level.nodes << " nodes, " << level.hostNodes
                    << " on the host, " << level.gpuMs << " GPU ms");
      if (hostRule && level.nodes < kHostLevelNodes) {
        CHECK(level.hostNodes == level.nodes);
        CHECK(level.gpuMs == 0);
        ++hostLevels;
      } else {
        CHECK(level.hostNodes == 0);
        if (context.timestampsSupported()) CHECK(level.gpuMs > 0);
        ++deviceLevels;
      }
    }
    CHECK((hostLevels > 0) == hostRule);
    CHECK(deviceLevels > 0);
  }
  test::requireValidationClean();
}

TEST_CASE("small levels on the host: a tree of small levels never asks the device",
          "[quadtree][tolerance]") {
  std::vector<BezierPatch> patches = readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt");
  patches.resize(4);
  const PatchSet set = toPatchSet(patches);
  auto hybrid = withSmallLevelsOnHost(std::make_unique<RefusingClassifier>(), size_t(1) << 20);
  auto mirror = makeMirrorClassifier();
  const QuadtreeOptions options = optionsFor(SplitRule::Tolerance);
  const QuadtreeResult a = buildQuadtree(set, options, *hybrid);
  const QuadtreeResult b = buildQuadtree(set, options, *mirror);
  REQUIRE(test::identicalTrees(a, b));
  REQUIRE(a.levels.size() > 1);
  for (const LevelStats& level : a.levels) CHECK(level.hostNodes == level.nodes);
}
