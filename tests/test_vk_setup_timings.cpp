// vk::ContextTimings (the Vulkan path's fixed cost, issue 15) and the evaluation pipeline built
// on a worker thread (PatchEvaluator::prepare, vk::BackgroundPipeline).
#include <catch2/catch.hpp>

#include <cstring>

#include "eval/evaluator.h"
#include "gpu_test_context.h"
#include "io/bpt_reader.h"
#include "vk/context.h"

using namespace tessera;

namespace {

std::vector<gpu::EvalQuery> cornerQueries(size_t patches) {
  std::vector<gpu::EvalQuery> queries;
  for (uint32_t p = 0; p < patches; ++p)
    for (float u : {0.0f, 0.5f, 1.0f}) queries.push_back({p, u, 1.0f - u, 0});
  return queries;
}

}  // namespace

TEST_CASE("a context times its setup, counts its pipelines and submissions",
          "[gpu][vk][timings]") {
  vk::Context& context = test::gpuContext();
  const vk::ContextTimings before = context.timings();
  INFO("instance " << before.instanceMs << " ms, device " << before.deviceMs << " ms");
  CHECK(before.instanceMs > 0);
  CHECK(before.deviceMs > 0);
  CHECK(before.contextMs() ==
        before.instanceMs + before.deviceMs + before.pipelineCacheMs);

  const PatchSet patches = toPatchSet(readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt"));
  auto evaluator = makeVulkanEvaluator(context);
  // No pipeline before it is needed or announced.
  CHECK(context.timings().pipelines == before.pipelines);
  evaluator->prepare(patches);
  const auto samples = evaluator->evaluate(patches, cornerQueries(patches.size()));
  const vk::ContextTimings after = context.timings();
  INFO("pipelines " << after.pipelinesMs - before.pipelinesMs << " ms, submits "
                    << after.submitsMs - before.submitsMs << " ms");
  CHECK(after.pipelines == before.pipelines + 1);  // eval.comp, once
  CHECK(after.pipelinesMs > before.pipelinesMs);
  CHECK(after.submits == before.submits + 1);
  CHECK(after.submitsMs > before.submitsMs);
  CHECK(after.firstSubmitMs > 0);
  CHECK(after.firstSubmitMs <= after.submitsMs);

  // prepare() again, and a second evaluation: the pipeline is kept, not rebuilt.
  evaluator->prepare(patches);
  evaluator->evaluate(patches, cornerQueries(patches.size()));
  CHECK(context.timings().pipelines == after.pipelines);
  test::requireValidationClean();
}

TEST_CASE("evaluation prepared on a worker thread equals evaluation built on first use",
          "[gpu][vk][timings]") {
  vk::Context& context = test::gpuContext();
  const PatchSet patches = toPatchSet(readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt"));
  const auto queries = cornerQueries(patches.size());
  auto prepared = makeVulkanEvaluator(context);
  prepared->prepare(patches);
  auto plain = makeVulkanEvaluator(context);
  const auto a = prepared->evaluate(patches, queries);
  const auto b = plain->evaluate(patches, queries);
  REQUIRE(a.size() == queries.size());
  REQUIRE(b.size() == queries.size());
  size_t differing = 0;
  for (size_t i = 0; i < a.size(); ++i)
    differing += std::memcmp(&a[i], &b[i], sizeof a[i]) != 0;
  INFO(differing << " of " << a.size() << " samples differ");
  CHECK(differing == 0);
  // An evaluator dropped while its pipeline is still building waits for it.
  makeVulkanEvaluator(context)->prepare(patches);
  test::requireValidationClean();
}
