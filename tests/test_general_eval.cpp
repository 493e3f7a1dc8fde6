// General patches (degree 1..7, rational; shaders/lib/general_eval.h):
// - the GPU shader (eval_general.comp.glsl) equals its fp32 mirror bit for bit on lavapipe,
//   for degree 2×2, 5×4, rational patches with an inner zero weight and a rational sphere
//   with collapsed sides;
// - the fp32 mirror against the double kernel (rational.h, surface_normal.h, curvature.h),
//   with the tolerances of test_eval_accuracy.cpp: position ≤ 2e-6 × the largest
//   coordinate (5e-6 for rational patches: the quotient adds a few roundings), normal ≤ 2e-4,
//   κ ≤ 1e-2 relative to max(κ, 1/L) where regular in both;
// - a bicubic patch degree-elevated to 5×4 is the same surface through the general path as
//   the original through the bicubic one.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

#include "geometry/curvature.h"
#include "geometry/degree_elevation.h"
#include "eval/evaluator.h"
#include "general_samples.h"
#include "gpu_test_context.h"
#include "patch_samples.h"
#include "geometry/rational.h"
#include "geometry/surface_normal.h"

using namespace tessera;

namespace {

// Largest |a − b| over every float of the samples, and how many floats differ in any bit.
std::pair<size_t, double> bitDifferences(const std::vector<gpu::EvalSample>& a,
                                         const std::vector<gpu::EvalSample>& b) {
  size_t mismatches = 0;
  double worst = 0;
  for (size_t i = 0; i < a.size(); ++i)
    for (int k = 0; k < 16; ++k) {
      const float x = (&a[i].position.x)[k], y = (&b[i].position.x)[k];
      if (std::memcmp(&x, &y, sizeof x) != 0) ++mismatches;
      worst = std::max(worst, double(std::fabs(x - y)));
    }
  return {mismatches, worst};
}

void checkGpuParity(const std::vector<BezierPatch>& input, const char* what) {
  vk::Context& context = test::gpuContext();
  GeneralPatchSet set = toGeneralPatchSet(input);
  auto queries = test::gridQueries(set.size(), 9, 64, 77);
  auto gpu = makeVulkanEvaluator(context)->evaluate(set, queries);
  auto cpu = makeMirrorEvaluator()->evaluate(set, queries);
  REQUIRE(gpu.size() == queries.size());
  auto [mismatches, worst] = bitDifferences(gpu, cpu);
  WARN(what << " on " << context.info().name << ": " << queries.size() << " queries, "
            << mismatches << " of " << 16 * queries.size()
            << " floats differ in any bit, largest difference " << worst);
  for (const auto& s : gpu)
    for (int k = 0; k < 4; ++k) REQUIRE(std::isfinite(s.normalKappa[k] + s.position[k]));
  if (context.info().isLavapipe())
    REQUIRE(mismatches == 0);
  else
    REQUIRE(worst <= 1e-3);  // fused multiply-adds elsewhere; lavapipe is the exact check
  test::requireValidationClean();
}

struct Accuracy {
  double posRel = 0, normal = 0, kappaRel = 0;
};

// The fp32 mirror against the double kernel on the fp32 inputs the mirror saw.
Accuracy accuracyOf(const std::vector<BezierPatch>& input) {
  GeneralPatchSet set = toGeneralPatchSet(input);
  auto queries = test::gridQueries(set.size(), 9, 32, 5);
  auto fp32 = makeMirrorEvaluator()->evaluate(set, queries);
  Accuracy a;
  for (size_t i = 0; i < queries.size(); ++i) {
    const gpu::GeneralPatch& g = set.patches[queries[i].patchIndex];
    RationalBezierPatch r;
    r.degreeU = int(g.degreeU);
    r.degreeV = int(g.degreeV);
    double coordinate = 0;
    for (size_t k = 0; k < size_t((g.degreeU + 1) * (g.degreeV + 1)); ++k) {
      const glm::dvec4 h(set.points[g.firstPoint + k]);
      r.cpw.push_back(h);
      if (h.w > 0) coordinate = std::max({coordinate, std::fabs(h.x / h.w), std::fabs(h.y / h.w), std::fabs(h.z / h.w)});
    }
    const double u = queries[i].u, v = queries[i].v;
    SurfaceDerivatives d = rationalPatchDerivatives(r, u, v);
    const double scale = controlNetDiagonal(r);
    const glm::dvec3 n = unitNormal(d, u, v, scale);
    const SurfaceCurvature c = surfaceCurvature(d, scale);
    const gpu::EvalSample& s = fp32[i];
    a.posRel = std::max(a.posRel, glm::length(glm::dvec3(glm::vec3(s.position)) - d.p) / coordinate);
    a.normal = std::max(a.normal, glm::length(glm::dvec3(glm::vec3(s.normalKappa)) - n));
    if (!c.degenerate && s.normalKappa.w > 0)
      a.kappaRel = std::max(a.kappaRel, std::fabs(double(s.normalKappa.w) - c.kappa) /
                                            std::max(c.kappa, 1.0 / scale));
  }
  return a;
}

}  // namespace

TEST_CASE("general eval shader equals its fp32 mirror: degree 2×2", "[gpu][parity][general]") {
  checkGpuParity(test::randomGeneralPatches(40, 2, 2, false, false, 11), "degree 2x2");
}

TEST_CASE("general eval shader equals its fp32 mirror: degree 5×4", "[gpu][parity][general]") {
  checkGpuParity(test::randomGeneralPatches(40, 5, 4, false, false, 12), "degree 5x4");
}

TEST_CASE("general eval shader equals its fp32 mirror: rational, inner zero weights",
          "[gpu][parity][general]") {
  checkGpuParity(test::randomGeneralPatches(40, 3, 4, true, false, 13), "rational 3x4");
  checkGpuParity(test::randomGeneralPatches(40, 4, 3, true, true, 14), "rational 4x3, inner w=0");
  checkGpuParity(test::rationalSphere(2.0), "rational sphere (collapsed poles)");
}

TEST_CASE("general fp32 evaluation against the double kernel", "[general][accuracy]") {
  struct Case {
    const char* what;
    std::vector<BezierPatch> patches;
    double posTolerance;
  };
  const Case cases[] = {
      {"degree 2x2", test::randomGeneralPatches(20, 2, 2, false, false, 21), 2e-6},
      {"degree 5x4", test::randomGeneralPatches(20, 5, 4, false, false, 22), 2e-6},
      {"degree 7x7", test::randomGeneralPatches(10, 7, 7, false, false, 23), 2e-6},
      {"rational 3x4", test::randomGeneralPatches(20, 3, 4, true, false, 24), 5e-6},
      {"rational 4x3, inner w=0", test::randomGeneralPatches(20, 4, 3, true, true, 25), 5e-6},
      {"rational sphere", test::rationalSphere(2.0), 5e-6},
      {"rational torus", test::rationalTorus(2.0, 0.7), 5e-6},
  };
  for (const Case& c : cases) {
    Accuracy a = accuracyOf(c.patches);
    WARN(c.what << ": max relative position error " << a.posRel << ", max normal error "
                << a.normal << ", max relative kappa error " << a.kappaRel);
    CHECK(a.posRel <= c.posTolerance);
    CHECK(a.normal <= 2e-4);
    CHECK(a.kappaRel <= 1e-2);
  }
}

TEST_CASE("a degree-elevated bicubic is the same surface through the general path",
          "[general][accuracy]") {
  auto bicubic = test::randomBicubicPatches(30, 31);
  std::vector<BezierPatch> elevated;
  for (const BezierPatch& p : bicubic) elevated.push_back(elevateDegreeTo(p, 5, 4));
  auto queries = test::gridQueries(bicubic.size(), 9, 16, 3);
  auto original = makeMirrorEvaluator()->evaluate(toGpuPatches(bicubic), queries);
  auto general = makeMirrorEvaluator()->evaluate(toGeneralPatchSet(elevated), queries);
  double posRel = 0, normal = 0;
  for (size_t i = 0; i < queries.size(); ++i) {
    const double size = std::max(1.0, double(glm::length(glm::vec3(original[i].position))));
    posRel = std::max(posRel, double(glm::length(glm::vec3(general[i].position - original[i].position))) / size);
    normal = std::max(normal, double(glm::length(glm::vec3(general[i].normalKappa - original[i].normalKappa))));
  }
  WARN("bicubic vs elevated to 5x4: max relative position difference " << posRel
       << ", max normal difference " << normal);
  REQUIRE(posRel <= 4e-6);
  REQUIRE(normal <= 1e-4);
}
