// Case 1, evaluation throughput, in one run on the same patches:
// - uniform P×P grids of bicubic patches, position + unit normal (32-byte vertices): scalar
//   CPU (fp32 mirror, one thread), all cores, Vulkan (one invocation per row of a grid,
//   shaders/grid_eval.comp.glsl) with the vertices left in the mapped buffer and copied out;
//   each as a fraction of the host-memory bandwidth cap;
// - point queries (position, Pu, Pv, normal, κ; one invocation per point re-reading 16 control
//   points, shaders/eval.comp.glsl): the double kernel (one thread), the fp32 mirror (all
//   cores from 8,192 queries: host/eval/evaluator_mirror.cpp), Vulkan;
// - the cost of one empty submit-and-wait round trip.
// Usage: bench_eval [patches=1024] [pointsPerSide=32] [queries=262144] [--json file]
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <thread>

#include "bench_args.h"
#include "bench_report.h"
#include "bench_scenes.h"
#include "geometry/bicubic.h"
#include "geometry/curvature.h"
#include "eval/evaluator.h"
#include "realtime/grid_evaluator.h"
#include "geometry/surface_normal.h"
#include "vk/context.h"

using namespace tessera;

namespace {

void gridCases(bench::Report& report, vk::Context& context,
               const std::vector<gpu::BicubicPatch>& patches, uint32_t n) {
  const double vertices = double(gridVertexCount(patches.size(), n));
  char title[160];
  std::snprintf(title, sizeof title,
                "grid evaluation: %zu bicubic patches x %ux%u points, position + normal (32 B)",
                patches.size(), n, n);
  bench::Table& table = report.table("evaluation", "points", title);
  auto scalar = makeMirrorGridEvaluator(1);
  auto parallel = makeMirrorGridEvaluator(0);
  auto vulkan = makeVulkanGridEvaluator(context);
  std::vector<gpu::GridVertex> copy(static_cast<size_t>(vertices));
  volatile float sink = 0;
  auto add = [&](const std::string& path, GridEvaluator& e, bool copyOut) {
    bench::Case c{path, vertices};
    c.timing = bench::timeRepeated(bench::kMinRuns, [&] {
      const gpu::GridVertex* out = e.evaluate(patches, n);
      if (copyOut) std::memcpy(copy.data(), out, copy.size() * sizeof(gpu::GridVertex));
      sink = sink + out[copy.size() / 2].position.x;
    });
    c.verticesPerSecond = vertices / c.timing.minSeconds;
    c.extra = {{"patches", patches.size()}, {"pointsPerSide", n}};
    table.cases.push_back(c);
  };
  add("scalar CPU (fp32 mirror, 1 thread)", *scalar, false);
  add("CPU, all " + std::to_string(std::thread::hardware_concurrency()) + " cores", *parallel,
      false);
  add("Vulkan, one invocation per row (vertices in the mapped buffer)", *vulkan, false);
  add("Vulkan, one invocation per row, copied to a std::vector", *vulkan, true);
  report.print(table);
}

void pointCases(bench::Report& report, vk::Context& context,
                const std::vector<BezierPatch>& patches, size_t queryCount) {
  auto gpuPatches = toGpuPatches(patches);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<gpu::EvalQuery> queries(queryCount);
  for (size_t i = 0; i < queryCount; ++i)
    queries[i] = {uint32_t(i / (queryCount / patches.size() + 1)), unit(rng), unit(rng), 0};
  char title[160];
  std::snprintf(title, sizeof title,
                "point queries: %zu random (u, v) on %zu patches, position, Pu, Pv, normal, "
                "kappa (64 B)", queryCount, patches.size());
  bench::Table& table = report.table("point evaluation", "points", title);
  std::vector<BicubicNet> nets(patches.size());
  std::vector<double> scales(patches.size());
  for (size_t p = 0; p < patches.size(); ++p) {
    for (int k = 0; k < 16; ++k) nets[p][k] = glm::dvec3(glm::vec3(gpuPatches[p].cp[k]));
    scales[p] = controlNetDiagonal(patches[p]);
  }
  volatile double sink = 0;
  bench::Case d{"scalar CPU (double kernel, 1 thread)", double(queryCount)};
  d.timing = bench::timeRepeated(bench::kMinRuns, [&] {
    double s = 0;
    for (const auto& q : queries) {
      SurfaceDerivatives sd = bicubicDerivatives(nets[q.patchIndex], q.u, q.v);
      glm::dvec3 n = unitNormal(sd, q.u, q.v, scales[q.patchIndex]);
      s += n.x + surfaceCurvature(sd, scales[q.patchIndex]).kappa;
    }
    sink = s;
  });
  table.cases.push_back(d);
  auto mirror = makeMirrorEvaluator();
  auto vulkan = makeVulkanEvaluator(context);
  for (PatchEvaluator* e : {mirror.get(), vulkan.get()}) {
    bench::Case c{e == mirror.get() ? "CPU (fp32 mirror, all cores from 8,192 queries)"
                                    : "Vulkan, one invocation per point (upload + dispatch + "
                                      "readback)",
                  double(queryCount)};
    c.timing = bench::timeRepeated(bench::kMinRuns, [&] { e->evaluate(gpuPatches, queries); });
    table.cases.push_back(c);
  }
  report.print(table);
}

}  // namespace

int main(int argc, char** argv) {
  bench::Report report(
      "bench_eval", "[patches=1024] [pointsPerSide=32] [queries=262144] [--json file]", argc, argv);
  bench::atMostArguments(report, argc, argv, 3);
  size_t patchCount =
      argc > 1 ? size_t(bench::integerArg(report, argv[1], "patches", 1, 1L << 20)) : 1024;
  uint32_t n =
      argc > 2 ? uint32_t(bench::integerArg(report, argv[2], "pointsPerSide", 2, 1024)) : 32;
  size_t queryCount = argc > 3 ? size_t(bench::integerArg(report, argv[3], "queries", 1, 1L << 26))
                               : size_t(1) << 18;
  auto patches = bench::randomPatches(patchCount);

  vk::ContextOptions options;
  vk::Context context(options);
  report.setDevice(context);
  gridCases(report, context, toGpuPatches(patches), n);
  pointCases(report, context, patches, queryCount);

  bench::Table& trip = report.table("round trip", "submits", "empty submit-and-wait round trip");
  bench::Case c{"vkQueueSubmit + fence wait, empty command buffer", 50};
  c.timing = bench::timeRepeated(bench::kMinRuns, [&] {
    for (int i = 0; i < 50; ++i) context.submitAndWait([](VkCommandBuffer) {});
  });
  trip.cases.push_back(c);
  report.print(trip);
  report.note("pipelineCache", {{"path", context.pipelineCachePath()},
                                {"loadedBytes", context.pipelineCacheLoadedBytes()}});
  report.finish();
  return 0;
}
