// Rule T on bicubic patches on Vulkan: from its second rule T tree on, the classifier builds the
// fused pipeline (quadtree_tolerance_fused.comp.glsl) in the background and, once it is built,
// decides a level in one dispatch instead of two. Its trees must be the two dispatches' and the
// fp32 mirror's (bit for bit where the device rounds as the mirror does), it must really be
// taken once built, and under a thread cap of 1 (no helper thread) never.
#include <catch2/catch.hpp>

#include <chrono>
#include <thread>

#include "common/thread_cap.h"
#include "eval/patch_set.h"
#include "gpu_test_context.h"
#include "io/bpt_reader.h"
#include "quadtree/quadtree.h"
#include "quadtree_compare.h"

using namespace tessera;

namespace {

size_t fusedNodes(const QuadtreeResult& tree) {
  size_t n = 0;
  for (const LevelStats& level : tree.levels) n += level.fusedNodes;
  return n;
}

size_t allNodes(const QuadtreeResult& tree) {
  size_t n = 0;
  for (const LevelStats& level : tree.levels) n += level.nodes;
  return n;
}

void requireSameTree(const QuadtreeResult& a, const QuadtreeResult& b) {
  if (test::exactMirrorArithmetic()) {
    REQUIRE(test::identicalTrees(a, b));
  } else {
    REQUIRE(double(a.leaves.size()) == Approx(double(b.leaves.size())).epsilon(0.02));
  }
}

}  // namespace

TEST_CASE("rule T's fused dispatch: the two dispatches' trees, taken once built",
          "[gpu][quadtree][tolerance][parity]") {
  vk::Context& context = test::gpuContext();
  const PatchSet teapot = toPatchSet(readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt"));
  const QuadtreeOptions options = toleranceOptions(0.02);  // the teapot's units
  auto mirror = makeMirrorClassifier();
  const QuadtreeResult expected = buildQuadtree(teapot, options, *mirror);
  auto device = makeVulkanClassifier(context);
  const QuadtreeResult twoDispatches = buildQuadtree(teapot, options, *device);
  CHECK(fusedNodes(twoDispatches) == 0);
  requireSameTree(twoDispatches, expected);
  // The second tree starts the build; the trees until it ends take the two dispatches (or,
  // where it ends within one, both kinds of level), and they all must agree.
  QuadtreeResult tree;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  do {
    tree = buildQuadtree(teapot, options, *device);
    requireSameTree(tree, twoDispatches);
    if (fusedNodes(tree) == allNodes(tree)) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  } while (std::chrono::steady_clock::now() < deadline);
  INFO(allNodes(tree) << " nodes, " << fusedNodes(tree) << " by the fused dispatch");
  REQUIRE(fusedNodes(tree) == allNodes(tree));
  requireSameTree(tree, expected);
  test::requireValidationClean();
}

TEST_CASE("rule T's fused dispatch: never under a thread cap of 1", "[gpu][quadtree][tolerance]") {
  vk::Context& context = test::gpuContext();
  std::vector<BezierPatch> patches = readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt");
  patches.resize(4);
  const PatchSet set = toPatchSet(patches);
  const QuadtreeOptions options = toleranceOptions(0.05);
  const ScopedThreadCap cap(1);
  auto device = makeVulkanClassifier(context);
  for (int tree = 0; tree < 3; ++tree) CHECK(fusedNodes(buildQuadtree(set, options, *device)) == 0);
  test::requireValidationClean();
}
