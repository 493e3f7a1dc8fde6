// Uniform-grid evaluation (shaders/grid_eval.comp.glsl, host/realtime/grid_evaluator.h): the shader
// against its fp32 mirror (bit for bit on lavapipe), and the mirror against the double kernel.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

#include "geometry/bicubic.h"
#include "eval/evaluator.h"
#include "gpu_test_context.h"
#include "realtime/grid_evaluator.h"
#include "io/bpt_reader.h"
#include "patch_samples.h"
#include "geometry/surface_normal.h"

using namespace tessera;

namespace {

std::vector<BezierPatch> testPatches() {
  auto patches = test::randomBicubicPatches(40, 7);
  for (const auto& p : test::collapsedEdgePatches()) patches.push_back(p);
  for (const auto& p : readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt")) patches.push_back(p);
  return patches;
}

}  // namespace

TEST_CASE("grid evaluation mirror agrees with the double kernel", "[grideval]") {
  auto patches = testPatches();
  auto gpuPatches = toGpuPatches(patches);
  const uint32_t n = 9;
  auto mirror = makeMirrorGridEvaluator(1);  // owns the result
  const gpu::GridVertex* grid = mirror->evaluate(gpuPatches, n);
  double maxPosition = 0, maxNormal = 0, maxCoordinate = 0;
  size_t missingNormals = 0;
  for (size_t p = 0; p < patches.size(); ++p) {
    BicubicNet net;
    for (int k = 0; k < 16; ++k) net[k] = glm::dvec3(glm::vec3(gpuPatches[p].cp[k]));
    BezierPatch rounded = patches[p];
    for (int k = 0; k < 16; ++k) rounded.cp[k] = net[k];
    double scale = controlNetDiagonal(rounded);
    for (uint32_t i = 0; i < n; ++i)
      for (uint32_t j = 0; j < n; ++j) {
        const gpu::GridVertex& g = grid[(p * n + i) * n + j];
        double u = double(i) / (n - 1), v = double(j) / (n - 1);
        SurfaceDerivatives d = bicubicDerivatives(net, u, v);
        glm::dvec3 normal = unitNormal(d, u, v, scale);
        maxCoordinate = std::max(maxCoordinate, glm::length(d.p));
        maxPosition = std::max(maxPosition, glm::length(glm::dvec3(glm::vec3(g.position)) - d.p));
        if (glm::length(normal) == 0 || glm::length(glm::vec3(g.normal)) == 0) {
          missingNormals += glm::length(normal) != glm::length(glm::dvec3(glm::vec3(g.normal)));
          continue;
        }
        maxNormal = std::max(maxNormal, glm::length(glm::dvec3(glm::vec3(g.normal)) - normal));
      }
  }
  WARN("grid mirror vs double on " << patches.size() << " patches: max |Δp| " << maxPosition
       << " (largest coordinate " << maxCoordinate << "), max |Δn| " << maxNormal
       << ", normals missing on one side only: " << missingNormals);
  CHECK(maxPosition <= 1e-5 * std::max(1.0, maxCoordinate));
  CHECK(maxNormal <= 1e-3);
  CHECK(missingNormals == 0);
}

TEST_CASE("grid evaluation on all cores equals one thread bit for bit", "[grideval]") {
  auto gpuPatches = toGpuPatches(testPatches());
  const uint32_t n = 7;
  std::vector<gpu::GridVertex> one(gridVertexCount(gpuPatches.size(), n));
  std::memcpy(one.data(), makeMirrorGridEvaluator(1)->evaluate(gpuPatches, n),
              one.size() * sizeof(gpu::GridVertex));  // copied before the evaluator goes
  auto parallel = makeMirrorGridEvaluator(3);
  const gpu::GridVertex* many = parallel->evaluate(gpuPatches, n);
  REQUIRE(std::memcmp(one.data(), many, one.size() * sizeof(gpu::GridVertex)) == 0);
  REQUIRE_THROWS_AS(makeMirrorGridEvaluator(1)->evaluate(gpuPatches, 1), std::invalid_argument);
}

TEST_CASE("grid_eval shader equals its fp32 mirror", "[gpu][parity][grideval]") {
  vk::Context& context = test::gpuContext();
  auto gpuPatches = toGpuPatches(testPatches());
  for (uint32_t n : {2u, 17u, 33u}) {
    const size_t count = gridVertexCount(gpuPatches.size(), n);
    auto vulkan = makeVulkanGridEvaluator(context);
    const gpu::GridVertex* gpu = vulkan->evaluate(gpuPatches, n);
    auto mirror = makeMirrorGridEvaluator(1);
    const gpu::GridVertex* cpu = mirror->evaluate(gpuPatches, n);
    size_t mismatches = 0;
    double maxPosition = 0, maxNormal = 0;
    for (size_t k = 0; k < count; ++k) {
      mismatches += std::memcmp(&gpu[k], &cpu[k], sizeof(gpu::GridVertex)) != 0;
      maxPosition = std::max(maxPosition, double(glm::length(gpu[k].position - cpu[k].position)));
      maxNormal = std::max(maxNormal, double(glm::length(gpu[k].normal - cpu[k].normal)));
    }
    WARN("grid " << n << "x" << n << " on " << gpuPatches.size() << " patches, "
                 << context.info().name << ": " << mismatches << " of " << count
                 << " vertices differ in any bit; max |Δp| " << maxPosition << ", max |Δn| "
                 << maxNormal);
    if (context.info().isLavapipe()) {
      REQUIRE(mismatches == 0);
    } else {
      REQUIRE(maxPosition <= 1e-5);
      REQUIRE(maxNormal <= 3e-5);
    }
  }
  test::requireValidationClean();
}
