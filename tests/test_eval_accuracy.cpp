// Accuracy of the GPU's fp32 evaluation against the double-precision kernel (bicubic.h,
// surface_normal.h, curvature.h), on the teapot and on random patches. Tolerances, stated:
//   position  ≤ 2e-6 × the patch's largest coordinate (a few fp32 ulps through 16 terms)
//   normal    ≤ 2e-4 absolute (unit vectors; the worst cases are near degenerate points,
//             where fp32 switches to the limiting direction at ε = 1e-5 but double at 1e-12)
//   κ         ≤ 1e-2 relative to max(κ, 1/L), where the point is regular in both
// Measured on lavapipe: teapot 3.6e-7, 3.2e-5, 4.2e-3; random patches 3.2e-7, 6.1e-6, 1.4e-5.
#include <catch2/catch.hpp>

#include <cmath>

#include "geometry/bicubic.h"
#include "geometry/curvature.h"
#include "eval/evaluator.h"
#include "gpu_test_context.h"
#include "io/bpt_reader.h"
#include "patch_samples.h"
#include "geometry/surface_normal.h"

using namespace tessera;

namespace {

void checkAccuracy(const std::vector<BezierPatch>& input, const char* what) {
  vk::Context& context = test::gpuContext();
  auto patches = toGpuPatches(input);
  auto queries = test::gridQueries(patches.size(), 9, 32, 5);
  auto gpu = makeVulkanEvaluator(context)->evaluate(patches, queries);
  double maxPosRel = 0, maxNormal = 0, maxKappaRel = 0, maxPosAbs = 0;
  size_t compared = 0;
  for (size_t i = 0; i < queries.size(); ++i) {
    // The reference sees exactly the fp32 inputs the GPU saw.
    BezierPatch p;
    p.cp.resize(16);
    double coordinate = 0;
    for (int k = 0; k < 16; ++k) {
      p.cp[k] = glm::dvec3(glm::vec3(patches[queries[i].patchIndex].cp[k]));
      coordinate = std::max({coordinate, std::fabs(p.cp[k].x), std::fabs(p.cp[k].y),
                             std::fabs(p.cp[k].z)});
    }
    double u = queries[i].u, v = queries[i].v;
    double L = controlNetDiagonal(p);
    SurfaceDerivatives d = bicubicDerivatives(p, u, v);
    glm::dvec3 n = unitNormal(d, u, v, L);
    SurfaceCurvature c = surfaceCurvature(d, L);
    const gpu::EvalSample& s = gpu[i];
    double dp = glm::length(glm::dvec3(glm::vec3(s.position)) - d.p);
    maxPosAbs = std::max(maxPosAbs, dp);
    maxPosRel = std::max(maxPosRel, dp / std::max(coordinate, 1e-30));
    maxNormal = std::max(maxNormal, glm::length(glm::dvec3(glm::vec3(s.normalKappa)) - n));
    if (!c.degenerate && s.normalKappa.w > 0) {
      double scale = std::max(c.kappa, 1.0 / L);
      maxKappaRel = std::max(maxKappaRel, std::fabs(s.normalKappa.w - c.kappa) / scale);
    }
    ++compared;
  }
  WARN(what << ": " << compared << " points; largest differences GPU fp32 vs double: position "
            << maxPosAbs << " (" << maxPosRel << " of the largest coordinate), normal "
            << maxNormal << ", κ " << maxKappaRel << " relative");
  REQUIRE(maxPosRel <= 2e-6);
  REQUIRE(maxNormal <= 2e-4);
  REQUIRE(maxKappaRel <= 1e-2);
  test::requireValidationClean();
}

}  // namespace

TEST_CASE("GPU evaluation matches the double kernel on the teapot", "[gpu][accuracy]") {
  checkAccuracy(readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt"), "teapot");
}

TEST_CASE("GPU evaluation matches the double kernel on random patches", "[gpu][accuracy]") {
  checkAccuracy(test::randomBicubicPatches(100, 2024), "random patches");
}

// CAD coordinates often sit far from the origin: derivatives must not lose digits to it.
TEST_CASE("GPU evaluation stays accurate far from the origin", "[gpu][accuracy]") {
  auto patches = test::randomBicubicPatches(100, 77);
  for (auto& p : patches)
    for (auto& c : p.cp) c += glm::dvec3(1000.0, -2000.0, 500.0);
  checkAccuracy(patches, "random patches offset by (1000, -2000, 500)");
}
