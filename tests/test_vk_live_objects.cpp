// A long-lived Context holds a bounded set of Vulkan objects: an engine calls Tessera every
// frame for hours, so after a warm-up (pipelines built, buffers grown to the work's size)
// repeated calls on one Context must leave as many live objects as they found: no command
// buffer, pool, fence, query pool, buffer or memory per call. Counted through the dispatch
// table (vk/object_census.h) on a Context of the test's own, made while the census is open.
// Each stage runs with its own submissions: the tessellation (quad-tree classifier and patch
// evaluator, Context::submitAndWait), the trim classifier (vk::AsyncSubmission, a pool of its
// own), the Loop stencil evaluator and the real-time frame (the stitch pattern).
#include <catch2/catch.hpp>

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "io/bpt_reader.h"
#include "loop/evaluator.h"
#include "loop/shapes.h"
#include "loop/stencils.h"
#include "loop/topology.h"
#include "mesh/tessellate.h"
#include "realtime/frame.h"
#include "trim/trim_classifier.h"
#include "trim_samples.h"
#include "vk/context.h"
#include "vk/object_census.h"

using namespace tessera;

namespace {

// Runs `call` a few times to warm up, then `rounds` times more: the live objects must not move.
void requireBoundedObjects(const vk::ObjectCensus& census, const char* what, int rounds,
                           const std::function<void()>& call) {
  for (int i = 0; i < 3; ++i) call();
  const vk::LiveObjects before = census.live();
  for (int i = 0; i < rounds; ++i) call();
  const vk::LiveObjects after = census.live();
  INFO(what << ": live after the warm-up: " << before.describe() << "; after " << rounds
            << " more calls: " << after.describe());
  CHECK(after == before);
}

}  // namespace

TEST_CASE("A long-lived Context holds a bounded set of Vulkan objects", "[gpu][vk][live]") {
  vk::ObjectCensus census;
  std::vector<std::string> messages;
  vk::ContextOptions options;
  options.validation = vk::Validation::Required;
  options.onValidationMessage = [&](const std::string& m) { messages.push_back(m); };
  vk::Context context(options);
  REQUIRE(census.live()[vk::ObjectKind::CommandPool] == 1);  // the census sees this context
  constexpr int kRounds = 100;

  std::vector<BezierPatch> teapot = readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt");
  {
    Backend gpu = makeVulkanBackend(context);
    const std::vector<BezierPatch> fewPatches(teapot.begin(), teapot.begin() + 2);
    QuadtreeOptions tree;
    tree.rule = SplitRule::TrueMax;
    requireBoundedObjects(census, "tessellate", kRounds,
                          [&] { tessellate(fewPatches, tree, gpu); });
  }
  {
    auto classifier = makeVulkanTrimClassifier(context);
    const TrimSet set = test::trimSampleSet();
    const auto queries = test::trimSampleQueries(set, 20, 7);
    requireBoundedObjects(census, "trim classify", kRounds,
                          [&] { classifier->classify(set, queries); });
  }
  {
    const LoopShape shape = loopIcosphere(1);
    const LoopStencils stencils =
        buildLoopStencils(buildLoopTopology(shape.topology), LoopStencilOptions{});
    const FloatStencilTable table = toFloatStencils(stencils.table);
    auto evaluator = makeVulkanStencilEvaluator(context, table, 3);
    std::vector<float> rows(table.rowCount() * 3, 0.0f);
    for (size_t v = 0; v < shape.positions.size(); ++v)
      for (int c = 0; c < 3; ++c) rows[3 * v + c] = float(shape.positions[v][c]);
    requireBoundedObjects(census, "Loop stencils", kRounds, [&] { evaluator->apply(rows); });
  }
  {
    RealtimeTessellator realtime(context, teapot);
    const Camera camera =
        lookAtCamera({6, -8, 4}, {0, 0, 1}, {0, 0, 1}, 0.8, 320, 180, 0.05, 200.0);
    requireBoundedObjects(census, "real-time frame", kRounds,
                          [&] { realtime.tessellate(camera); });
  }
  for (const std::string& m : messages) UNSCOPED_INFO(m);
  CHECK(messages.empty());
}
