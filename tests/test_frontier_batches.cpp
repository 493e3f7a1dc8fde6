// The bounded frontier (host/quadtree/frontier.cpp): a level larger than one batch — set by the
// frontier memory budget or by the classifier's largest buffer — is classified in batches,
// depth first, and a patch set larger than the classifier's patch buffer is split into
// groups. Neither may change the tree: the same leaves, bit for bit (in another order), the
// same nodes per level; and the frontier stays within its budget.
#include <catch2/catch.hpp>

#include <algorithm>
#include <tuple>

#include "eval/evaluator.h"
#include "geometry/general_patch.h"
#include "general_samples.h"
#include "gpu_test_context.h"
#include "io/bpt_reader.h"
#include "quadtree/quadtree.h"
#include "quadtree_compare.h"

using namespace tessera;

namespace {

// The mirror classifier with a GPU's limits, made small, recording what it was given.
class LimitedClassifier : public NodeClassifier {
 public:
  LimitedClassifier(size_t batchNodes, size_t patchBytes)
      : inner_(makeMirrorClassifier()), batchNodes_(batchNodes), patchBytes_(patchBytes) {}
  std::string name() const override { return "limited mirror"; }
  size_t maxBatchNodes() const override { return batchNodes_; }
  size_t maxPatchBufferBytes() const override { return patchBytes_; }
  void beginTree(const PatchSet& patches) override {
    if (patches.isBicubic()) {
      largestPatchBytes =
          std::max(largestPatchBytes, patches.size() * sizeof(gpu::BicubicPatch));
    } else {
      const GeneralPatchSet& general = patches.general();
      largestPatchBytes = std::max({largestPatchBytes,
                                    general.patches.size() * sizeof(gpu::GeneralPatch),
                                    general.points.size() * sizeof(gpu::vec4)});
    }
    inner_->beginTree(patches);
  }
  void classify(const PatchSet& patches, const std::vector<gpu::QuadNode>& nodes,
                const QuadtreeOptions& options, std::vector<gpu::NodeDecision>& decisions,
                LevelStats& stats) override {
    largestBatch = std::max(largestBatch, nodes.size());
    inner_->classify(patches, nodes, options, decisions, stats);
  }
  size_t largestBatch = 0, largestPatchBytes = 0;

 private:
  std::unique_ptr<NodeClassifier> inner_;
  size_t batchNodes_, patchBytes_;
};

// Leaves in (patch, path) order, so trees built in different orders compare leaf by leaf.
QuadtreeResult sortedLeaves(QuadtreeResult tree) {
  std::sort(tree.leaves.begin(), tree.leaves.end(), [](const QuadLeaf& a, const QuadLeaf& b) {
    return std::tie(a.patchIndex, a.level, a.path) < std::tie(b.patchIndex, b.level, b.path);
  });
  return tree;
}

void requireSameTree(const QuadtreeResult& batched, const QuadtreeResult& whole) {
  REQUIRE(batched.leaves.size() == whole.leaves.size());
  REQUIRE(test::identicalTrees(sortedLeaves(batched), sortedLeaves(whole)));
  REQUIRE(batched.levels.size() == whole.levels.size());
  for (size_t l = 0; l < whole.levels.size(); ++l) {
    REQUIRE(batched.levels[l].nodes == whole.levels[l].nodes);
    REQUIRE(batched.levels[l].leaves == whole.levels[l].leaves);
  }
  REQUIRE(batched.depth == whole.depth);
}

QuadtreeOptions teapotOptions(SplitRule rule) {
  // Rule T at δ = 10⁻² (about 1.2·10⁻³ of the teapot's size), with its grid splits of up to
  // toleranceSplitCap² children a node.
  if (rule == SplitRule::Tolerance) return toleranceOptions(1e-2);
  QuadtreeOptions o;
  o.rule = rule;
  o.linearity = o.flatness = 0.05f;
  return o;
}

}  // namespace

TEST_CASE("frontier: a small budget batches levels without changing the tree", "[quadtree][frontier]") {
  const auto teapot = toGpuPatches(readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt"));
  for (SplitRule rule : {SplitRule::Midpoint, SplitRule::TrueMax, SplitRule::Tolerance}) {
    QuadtreeOptions whole = teapotOptions(rule);
    auto mirror = makeMirrorClassifier();
    const QuadtreeResult reference = buildQuadtree(teapot, whole, *mirror);
    REQUIRE(reference.batches == reference.levels.size());  // nothing split up by default

    QuadtreeOptions small = whole;
    // ~39 nodes a batch at depth 12 (B, D); rule T's 16 children a node at depth 30 need
    // ((16 − 1)·30 + 17)·33 bytes a batch node: ~40 nodes.
    small.frontierBudgetBytes = rule == SplitRule::Tolerance ? 640 * 1024 : 64 * 1024;
    const size_t batchNodes = frontierBatchNodes(small, SIZE_MAX);
    LimitedClassifier limited(SIZE_MAX, SIZE_MAX);
    const QuadtreeResult batched = buildQuadtree(teapot, small, limited);
    size_t largestLevel = 0;
    for (const auto& l : reference.levels) largestLevel = std::max(largestLevel, l.nodes);
    INFO("rule " << splitRuleLetter(rule) << ": " << reference.leaves.size() << " leaves; largest level "
                 << largestLevel << " nodes (peak frontier " << reference.peakFrontierNodes
                 << " unbatched); batches of " << batchNodes << ": " << batched.batches
                 << " batches, peak frontier " << batched.peakFrontierNodes << " nodes");
    requireSameTree(batched, reference);
    REQUIRE(limited.largestBatch <= batchNodes);
    REQUIRE(batched.batches > 10 * reference.batches);
    // The bound the batch size is chosen for: waiting nodes, the batch and its children.
    REQUIRE(batched.peakFrontierNodes * kFrontierBytesPerNode +
                batchNodes * sizeof(gpu::NodeDecision) <= small.frontierBudgetBytes);
    REQUIRE(batched.peakFrontierNodes * 5 < reference.peakFrontierNodes);  // T: 16 children a node
  }
}

TEST_CASE("frontier: the classifier's buffer limits split batches and patch groups", "[quadtree][frontier]") {
  const auto teapot = toGpuPatches(readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt"));
  const QuadtreeOptions o = teapotOptions(SplitRule::SampledMax);
  auto mirror = makeMirrorClassifier();
  const QuadtreeResult reference = buildQuadtree(teapot, o, *mirror);

  LimitedClassifier limited(37, 5 * sizeof(gpu::BicubicPatch));  // 37 nodes, 5 patches
  const QuadtreeResult grouped = buildQuadtree(teapot, o, limited);
  requireSameTree(grouped, reference);
  CHECK(grouped.patchGroups == 7);  // ⌈32 / 5⌉
  CHECK(limited.largestBatch <= 37);
  CHECK(limited.largestPatchBytes <= 5 * sizeof(gpu::BicubicPatch));
}

TEST_CASE("frontier: general patch sets are grouped with their control points", "[quadtree][frontier]") {
  std::vector<BezierPatch> scene = test::rationalSphere(1.0);
  for (const auto& p : test::rationalTorus(3.0, 1.0)) scene.push_back(p);
  const GeneralPatchSet set = toGeneralPatchSet(scene);
  QuadtreeOptions o;
  o.rule = SplitRule::Midpoint;
  o.linearity = o.flatness = 0.05f;
  auto mirror = makeMirrorClassifier();
  const QuadtreeResult reference = buildQuadtree(set, o, *mirror);
  // Room for 9 control points of a biquadratic patch and a little more: one patch per group.
  LimitedClassifier limited(64, 12 * sizeof(gpu::vec4));
  const QuadtreeResult grouped = buildQuadtree(set, o, limited);
  requireSameTree(grouped, reference);
  CHECK(grouped.patchGroups == scene.size());
  CHECK(limited.largestBatch <= 64);

  LimitedClassifier tooSmall(64, 4 * sizeof(gpu::vec4));
  REQUIRE_THROWS_AS(buildQuadtree(set, o, tooSmall), TessellationLimitError);
}

TEST_CASE("frontier: a budget that holds no batch is refused", "[quadtree][frontier]") {
  QuadtreeOptions o;
  o.frontierBudgetBytes = 100;
  auto mirror = makeMirrorClassifier();
  REQUIRE_THROWS_WITH(buildQuadtree(toGpuPatches(readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt")), o, *mirror),
                      Catch::Contains("frontier budget of 100 bytes"));
}

TEST_CASE("frontier: Vulkan in small batches equals the mirror's whole levels", "[gpu][quadtree][frontier]") {
  const auto teapot = toGpuPatches(readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt"));
  auto gpu = makeVulkanClassifier(test::gpuContext());
  CHECK(gpu->maxBatchNodes() * sizeof(gpu::QuadNode) <= test::gpuContext().info().maxStorageBufferRange);
  for (SplitRule rule : {SplitRule::TrueMax, SplitRule::Tolerance}) {
    QuadtreeOptions o = teapotOptions(rule);
    // The mirror's whole levels where the device rounds as the mirror does; elsewhere the
    // device's own whole levels (batching must not change a decision on any device).
    auto mirror = makeMirrorClassifier();
    const QuadtreeResult reference =
        buildQuadtree(teapot, o, test::exactMirrorArithmetic() ? *mirror : *gpu);
    // D: ~150 nodes a batch; T (16 children a node, depth 30): ~40.
    o.frontierBudgetBytes = rule == SplitRule::Tolerance ? 640 * 1024 : 256 * 1024;
    const QuadtreeResult batched = buildQuadtree(teapot, o, *gpu);
    INFO("rule " << splitRuleLetter(rule) << ": " << batched.batches << " Vulkan batches against "
                 << reference.batches << " levels");
    requireSameTree(batched, reference);
    REQUIRE(batched.batches > 10 * reference.batches);
  }
  test::requireValidationClean();
}
