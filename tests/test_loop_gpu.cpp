// Loop stencils on Vulkan (shaders/loop_stencil.comp.glsl) against the fp32 mirror and the double
// reference: levels 1–3, limit positions and tangents, chained (one batch per level, each
// reading the last) and factorized (one batch). On lavapipe, which does not fuse multiply-adds,
// shader and mirror agree bit for bit; against double the difference stays below 2e-6 × the
// largest value (fp32 rounding accumulates over the levels, see docs/loop.md).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

#include "gpu_test_context.h"
#include "loop/evaluator.h"
#include "loop/shapes.h"

using namespace tessera;

namespace {

struct StencilParity {
  size_t bitMismatches = 0;
  double worstVsMirror = 0, worstVsDouble = 0, largest = 0;
};

StencilParity runParity(const LoopShape& shape, const LoopStencilOptions& options,
                        uint32_t width, const VulkanStencilOptions& vulkan = {}) {
  LoopStencils stencils = buildLoopStencils(buildLoopTopology(shape.topology), options);
  const FloatStencilTable table = toFloatStencils(stencils.table);
  std::vector<float> gpu(table.rowCount() * width, 0.0f);
  // Positions, then extra channels (e.g. a colour) as any per-vertex data.
  for (size_t v = 0; v < shape.positions.size(); ++v)
    for (uint32_t c = 0; c < width; ++c)
      gpu[v * width + c] = c < 3 ? float(shape.positions[v][c]) : float(std::sin(0.3 * v + c));
  std::vector<float> mirror = gpu, reference = gpu;
  vk::Context& context = test::gpuContext();
  makeVulkanStencilEvaluator(context, table, width, vulkan)->apply(gpu);
  makeMirrorStencilEvaluator(table, width)->apply(mirror);
  makeReferenceStencilEvaluator(stencils.table, width)->apply(reference);
  StencilParity r;
  for (size_t i = 0; i < gpu.size(); ++i) {
    REQUIRE(std::isfinite(gpu[i]));
    if (std::memcmp(&gpu[i], &mirror[i], sizeof(float)) != 0) ++r.bitMismatches;
    r.worstVsMirror = std::max(r.worstVsMirror, double(std::fabs(gpu[i] - mirror[i])));
    r.worstVsDouble = std::max(r.worstVsDouble, double(std::fabs(gpu[i] - reference[i])));
    r.largest = std::max(r.largest, double(std::fabs(reference[i])));
  }
  return r;
}

}  // namespace

TEST_CASE("Loop stencils on Vulkan: bit-exact with the fp32 mirror, close to double", "[gpu][loop]") {
  vk::Context& context = test::gpuContext();
  for (const LoopShape& s : {loopBunny(3, 8), loopGrid(9, 7, 3), loopCreasedSphere(2, 5),
                             loopTorus(16, 8, 0.05, 6)}) {
    for (bool factorize : {false, true}) {
      INFO(s.name << (factorize ? ", factorized" : ", chained"));
      LoopStencilOptions options;
      options.levels = 3;
      options.limit = options.tangents = true;
      options.factorize = factorize;
      const uint32_t width = factorize ? 3 : 4;
      StencilParity r = runParity(s, options, width);
      WARN(s.name << (factorize ? " factorized" : " chained") << " on " << context.info().name
                  << ": " << r.bitMismatches << " floats differ from the mirror (max "
                  << r.worstVsMirror << "), max |GPU − double| " << r.worstVsDouble
                  << " (largest value " << r.largest << ")");
      if (context.info().isLavapipe()) REQUIRE(r.bitMismatches == 0);
      REQUIRE(r.worstVsMirror <= 1e-6 * r.largest);
      REQUIRE(r.worstVsDouble <= 2e-6 * r.largest);
    }
  }
  test::requireValidationClean();
}

TEST_CASE("Loop stencils on Vulkan: the EdgeOnly boundary rule as on the mirror", "[gpu][loop]") {
  // The stencils carry the rule, so every backend follows it: bit-exact with the mirror on
  // lavapipe, close to double.
  vk::Context& context = test::gpuContext();
  LoopShape s = loopGrid(9, 7, 3);
  s.topology.boundary = LoopBoundary::EdgeOnly;
  LoopStencilOptions options;
  options.levels = 3;
  options.limit = options.tangents = true;
  const StencilParity r = runParity(s, options, 3);
  WARN(s.name << " EdgeOnly on " << context.info().name << ": " << r.bitMismatches
              << " floats differ from the mirror, max |GPU − double| " << r.worstVsDouble);
  if (context.info().isLavapipe()) REQUIRE(r.bitMismatches == 0);
  REQUIRE(r.worstVsDouble <= 2e-6 * r.largest);
  test::requireValidationClean();
}

TEST_CASE("Loop stencils on Vulkan: apply() again with new control data", "[gpu][loop]") {
  // An evaluator keeps its table: moving the control vertices (as fitting does) and applying
  // again gives the refinement of the new cage.
  vk::Context& context = test::gpuContext();
  LoopShape s = loopIcosphere(2);
  LoopStencilOptions options;
  options.levels = 2;
  LoopStencils stencils = buildLoopStencils(buildLoopTopology(s.topology), options);
  const FloatStencilTable table = toFloatStencils(stencils.table);
  auto gpu = makeVulkanStencilEvaluator(context, table, 3);
  auto mirror = makeMirrorStencilEvaluator(table, 3);
  for (double scale : {1.0, 2.5}) {
    std::vector<float> a(table.rowCount() * 3, 0.0f);
    for (size_t v = 0; v < s.positions.size(); ++v)
      for (int c = 0; c < 3; ++c) a[3 * v + c] = float(scale * s.positions[v][c]);
    std::vector<float> b = a;
    gpu->apply(a);
    mirror->apply(b);
    const bool identical = std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
    if (context.info().isLavapipe()) REQUIRE(identical);
    // A sphere's refinement shrinks towards the centre but scales with the cage.
    const size_t last = table.rowCount() - 1;
    const double radius = std::sqrt(double(a[3 * last] * a[3 * last] + a[3 * last + 1] * a[3 * last + 1] +
                                           a[3 * last + 2] * a[3 * last + 2]));
    REQUIRE(radius > 0.85 * scale);
    REQUIRE(radius < 1.0 * scale);
  }
  test::requireValidationClean();
}

TEST_CASE("Loop stencils on Vulkan: a table past the array bound goes in slices, bit for bit",
          "[gpu][loop]") {
  // A bound of a few hundred bytes stands in for a table larger than maxStorageBufferRange
  // (lavapipe: 128 MiB, reached by `tessera limit data/loop/torus.obj -l 7`): the same result
  // as the mirror, now in many submissions.
  vk::Context& context = test::gpuContext();
  for (const bool factorize : {false, true}) {
    LoopShape s = loopTorus(8, 6, 0.05, 3);
    LoopStencilOptions options;
    options.levels = 2;
    options.limit = options.tangents = true;
    options.factorize = factorize;
    VulkanStencilOptions vulkan;
    vulkan.maxArrayBytes = factorize ? 2048 : 384;
    const FloatStencilTable table =
        toFloatStencils(buildLoopStencils(buildLoopTopology(s.topology), options).table);
    const auto evaluator = makeVulkanStencilEvaluator(context, table, 3, vulkan);
    INFO(evaluator->name());
    REQUIRE(evaluator->name().find(" batches") != std::string::npos);
    const StencilParity r = runParity(s, options, 3, vulkan);
    WARN(s.name << (factorize ? " factorized" : " chained") << " in slices of "
                << vulkan.maxArrayBytes << " bytes (" << evaluator->name() << "): "
                << r.bitMismatches << " floats differ from the mirror");
    if (context.info().isLavapipe()) REQUIRE(r.bitMismatches == 0);
    REQUIRE(r.worstVsMirror <= 1e-6 * r.largest);
    REQUIRE(r.worstVsDouble <= 2e-6 * r.largest);
  }
  // Level 0: no stencils, but control rows past the bound: nothing to run, rows kept.
  LoopStencilOptions none;
  none.levels = 0;
  const LoopShape ball = loopIcosphere(2);
  const FloatStencilTable empty =
      toFloatStencils(buildLoopStencils(buildLoopTopology(ball.topology), none).table);
  REQUIRE(empty.stencilCount() == 0);
  const auto evaluator = makeVulkanStencilEvaluator(context, empty, 3, {64});
  REQUIRE(evaluator->name().find(" in 0 batches") != std::string::npos);
  std::vector<float> rows(empty.rowCount() * 3, 0.5f);
  evaluator->apply(rows);
  REQUIRE(rows == std::vector<float>(empty.rowCount() * 3, 0.5f));
  test::requireValidationClean();
}
