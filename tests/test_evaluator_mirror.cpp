// The fp32 mirror evaluator takes a large batch on all cores (host/eval/evaluator_mirror.cpp):
// every sample must still be its query's, bit for bit, as one call per query gives it.
#include <catch2/catch.hpp>

#include <cstring>

#include "eval/detail/bicubic_mirror.h"
#include "eval/evaluator.h"
#include "patch_samples.h"

using namespace tessera;

TEST_CASE("fp32 mirror evaluator: a batch on all cores gives each query's sample",
          "[eval][mirror]") {
  const std::vector<gpu::BicubicPatch> patches = toGpuPatches(test::randomBicubicPatches(120, 7));
  // 120 patches × (13² + 40) queries, a patch's together: over 25,000, several chunks of the
  // parallel path, most of them across patches.
  const std::vector<gpu::EvalQuery> queries = test::gridQueries(patches.size(), 13, 40, 99);
  REQUIRE(queries.size() > 3 * 8192);
  const std::vector<gpu::EvalSample> batch = makeMirrorEvaluator()->evaluate(patches, queries);
  REQUIRE(batch.size() == queries.size());
  size_t differing = 0;
  for (size_t i = 0; i < queries.size(); ++i) {
    const gpu::EvalQuery& q = queries[i];
    const gpu::EvalSample one =
        mirror::evalBicubicSample(patches[q.patchIndex], q.u, q.v, kDegenerateEpsFp32);
    differing += std::memcmp(&one, &batch[i], sizeof one) != 0;
  }
  REQUIRE(differing == 0);
}
