// Points evaluated per second (position, Pu, Pv, unit normal, κ of bicubic patches):
// scalar CPU (the double kernel, and the fp32 mirror, one thread) vs Vulkan, the same
// queries, in one run;
// plus the cost of one submit-and-wait round trip. Usage: bench_eval [queries]
#include <cstdio>
#include <cstdlib>
#include <random>

#include "bench_common.h"
#include "bicubic.h"
#include "curvature.h"
#include "surface_normal.h"
#include "evaluator.h"
#include "vk/context.h"

using namespace tessera;

int main(int argc, char** argv) {
  size_t queryCount = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1u << 20;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<gpu::BicubicPatch> patches(1024);
  for (auto& p : patches)
    for (int k = 0; k < 16; ++k)
      p.cp[k] = gpu::vec4(float(k / 4) + unit(rng) * 0.3f, float(k % 4) + unit(rng) * 0.3f,
                          unit(rng), 1.0f);
  std::vector<gpu::EvalQuery> queries(queryCount);
  for (size_t i = 0; i < queryCount; ++i)
    queries[i] = {uint32_t(i / (queryCount / patches.size() + 1)), unit(rng), unit(rng), 0};

  vk::ContextOptions options;
  vk::Context context(options);
  auto gpu = makeVulkanEvaluator(context);
  auto cpu = makeMirrorEvaluator();

  auto cpuTime = bench::timeRepeated(3, [&] { cpu->evaluate(patches, queries); });
  // The double kernel on the same queries: the scalar CPU reference.
  std::vector<BicubicNet> nets(patches.size());
  std::vector<double> scales(patches.size());
  for (size_t p = 0; p < patches.size(); ++p) {
    BezierPatch bp;
    bp.cp.resize(16);
    for (int k = 0; k < 16; ++k) bp.cp[k] = nets[p][k] = glm::dvec3(glm::vec3(patches[p].cp[k]));
    scales[p] = controlNetDiagonal(bp);
  }
  double sink = 0;
  auto doubleTime = bench::timeRepeated(3, [&] {
    for (const auto& q : queries) {
      SurfaceDerivatives d = bicubicDerivatives(nets[q.patchIndex], q.u, q.v);
      glm::dvec3 n = unitNormal(d, q.u, q.v, scales[q.patchIndex]);
      sink += n.x + surfaceCurvature(d, scales[q.patchIndex]).kappa;
    }
  });
  auto gpuTime = bench::timeRepeated(5, [&] { gpu->evaluate(patches, queries); });
  auto roundTrip = bench::timeRepeated(50, [&] { context.submitAndWait([](VkCommandBuffer) {}); });

  double cpuRate = queryCount / cpuTime.minSeconds;
  double doubleRate = queryCount / doubleTime.minSeconds;
  double gpuRate = queryCount / gpuTime.minSeconds;
  std::printf("bench_eval: %zu queries on %zu bicubic patches\n", queryCount, patches.size());
  std::printf("device: %s (%s)\n", context.info().name.c_str(), context.info().driverInfo.c_str());
  std::printf("| path | min s | median s | points/s | ratio to scalar CPU |\n|---|---|---|---|---|\n");
  std::printf("| scalar CPU (double kernel, 1 thread) | %.4f | %.4f | %.3g | 1.00 |\n",
              doubleTime.minSeconds, doubleTime.medianSeconds, doubleRate);
  std::printf("| scalar CPU (fp32 mirror, 1 thread) | %.4f | %.4f | %.3g | %.2f |\n",
              cpuTime.minSeconds, cpuTime.medianSeconds, cpuRate, cpuRate / doubleRate);
  std::printf("| Vulkan (upload + dispatch + readback) | %.4f | %.4f | %.3g | %.2f |\n",
              gpuTime.minSeconds, gpuTime.medianSeconds, gpuRate, gpuRate / doubleRate);
  std::printf("submit-and-wait round trip (empty command buffer): min %.1f us, median %.1f us\n",
              roundTrip.minSeconds * 1e6, roundTrip.medianSeconds * 1e6);
  return sink == 12345.678 ? 1 : 0;  // keeps the double loop from being optimised away
}
