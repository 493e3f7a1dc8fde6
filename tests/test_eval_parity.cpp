// GPU evaluation (shaders/eval.comp.glsl) against its fp32 mirror. On lavapipe, which does
// not fuse multiply-adds, the two must agree bit for bit; on other drivers within the stated
// tolerance (positions 1e-6 × the largest coordinate, normals 3e-5).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

#include "eval/evaluator.h"
#include "gpu_test_context.h"
#include "patch_samples.h"

using namespace tessera;

namespace {

struct ParityReport {
  size_t values = 0;
  size_t bitMismatches = 0;
  double maxPositionDiff = 0, maxNormalDiff = 0, maxKappaRel = 0, maxCoordinate = 0;
};

ParityReport compare(const std::vector<gpu::EvalSample>& a, const std::vector<gpu::EvalSample>& b) {
  ParityReport r;
  for (size_t i = 0; i < a.size(); ++i) {
    const float* fa = &a[i].position.x;
    const float* fb = &b[i].position.x;
    for (int k = 0; k < 16; ++k) {
      ++r.values;
      if (std::memcmp(fa + k, fb + k, sizeof(float)) != 0) ++r.bitMismatches;
    }
    for (int c = 0; c < 3; ++c) {
      r.maxCoordinate = std::max(r.maxCoordinate, double(std::fabs(a[i].position[c])));
      r.maxPositionDiff =
          std::max(r.maxPositionDiff, double(std::fabs(a[i].position[c] - b[i].position[c])));
      r.maxNormalDiff = std::max(r.maxNormalDiff,
                                 double(std::fabs(a[i].normalKappa[c] - b[i].normalKappa[c])));
    }
    double ka = a[i].normalKappa.w, kb = b[i].normalKappa.w;
    r.maxKappaRel = std::max(r.maxKappaRel, std::fabs(ka - kb) / std::max(1.0, std::fabs(ka)));
  }
  return r;
}

void checkParity(const std::vector<BezierPatch>& patches, const char* what) {
  vk::Context& context = test::gpuContext();
  auto gpuPatches = toGpuPatches(patches);
  auto queries = test::gridQueries(gpuPatches.size(), 9, 64, 1234);
  auto gpu = makeVulkanEvaluator(context)->evaluate(gpuPatches, queries);
  auto cpu = makeMirrorEvaluator()->evaluate(gpuPatches, queries);
  REQUIRE(gpu.size() == queries.size());
  ParityReport r = compare(gpu, cpu);
  WARN(what << " on " << context.info().name << ": " << queries.size() << " queries, "
            << r.bitMismatches << " of " << r.values << " floats differ in any bit; max |Δp| "
            << r.maxPositionDiff << " (largest coordinate " << r.maxCoordinate << "), max |Δn| "
            << r.maxNormalDiff << ", max relative Δκ " << r.maxKappaRel);
  for (const auto& s : gpu)
    for (int k = 0; k < 4; ++k) REQUIRE(std::isfinite(s.normalKappa[k]));
  if (context.info().isLavapipe()) {
    REQUIRE(r.bitMismatches == 0);
  } else {
    REQUIRE(r.maxPositionDiff <= 1e-6 * std::max(1.0, r.maxCoordinate));
    REQUIRE(r.maxNormalDiff <= 3e-5);
  }
  test::requireValidationClean();
}

}  // namespace

TEST_CASE("eval shader equals its fp32 mirror on random bicubic patches", "[gpu][parity]") {
  checkParity(test::randomBicubicPatches(200, 42), "random patches");
}

TEST_CASE("eval shader equals its fp32 mirror on patches with collapsed edges", "[gpu][parity]") {
  checkParity(test::collapsedEdgePatches(), "collapsed-edge patches");
}
