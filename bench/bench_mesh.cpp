// Final-mesh generation: from finished quad-trees to a watertight indexed mesh — leaf
// triangulation with stitching across patches (CPU), then positions and normals of every
// vertex evaluated in one batch, on Vulkan or on the scalar CPU (the fp32 mirror) — in
// triangles per second, on the teapot ×N, in one run. Usage: bench_mesh [instances=1000]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "bench_common.h"
#include "io/bpt_reader.h"
#include "tessellate.h"
#include "vk/context.h"

using namespace tessera;

namespace {

// Copies moved apart and bent by smooth fields, so shared edges stay shared (bench_quadtree).
std::vector<BezierPatch> teapots(const std::vector<BezierPatch>& teapot, int count) {
  std::mt19937 rng(1234);
  std::uniform_real_distribution<double> phase(0.0, 6.2831853);
  std::vector<BezierPatch> out;
  for (int c = 0; c < count; ++c) {
    glm::dvec3 offset(double(c % 40) * 8.0, double(c / 40) * 8.0, 0.0);
    double a = phase(rng), b = phase(rng), d = phase(rng);
    for (BezierPatch p : teapot) {
      for (auto& cp : p.cp)
        cp += offset + glm::dvec3(0.02 * std::sin(1.3 * cp.y + a), 0.02 * std::sin(1.1 * cp.z + b),
                                  0.02 * std::sin(0.9 * cp.x + d));
      out.push_back(p);
    }
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  int instances = argc > 1 ? std::atoi(argv[1]) : 1000;
  auto patches = teapots(readBpt(TESSERA_BENCH_DATA "/teapot.bpt"), instances);
  auto gpuPatches = toGpuPatches(patches);
  vk::ContextOptions options;
  vk::Context context(options);
  Backend vulkan = makeVulkanBackend(context);
  auto cpuEvaluator = makeMirrorEvaluator();

  QuadtreeOptions q;
  q.rule = SplitRule::Midpoint;
  QuadtreeResult tree = buildQuadtree(gpuPatches, q, *vulkan.classifier);
  std::printf("bench_mesh on %s: teapot x%d (%zu patches), rule B at 0.1: %zu leaves\n\n",
              context.info().name.c_str(), instances, patches.size(), tree.leaves.size());

  Tessellation gpu, cpu;
  auto gpuTime = bench::timeRepeated(3, [&] { gpu = meshFromTree(patches, gpuPatches, tree, *vulkan.evaluator); });
  auto cpuTime = bench::timeRepeated(3, [&] { cpu = meshFromTree(patches, gpuPatches, tree, *cpuEvaluator); });
  if (gpu.mesh.indices != cpu.mesh.indices) std::printf("WARNING: the two meshes differ\n");
  double tris = double(gpu.mesh.triangleCount());
  std::printf("%zu triangles, %zu vertices\n\n", gpu.mesh.triangleCount(), gpu.mesh.vertexCount());
  std::printf("| vertex evaluation | min s | median s | triangles/s | ratio | of which: triangulation ms, evaluation ms |\n|---|---|---|---|---|---|\n");
  std::printf("| scalar CPU (fp32 mirror) | %.3f | %.3f | %.3g | 1.00 | %.0f, %.0f |\n", cpuTime.minSeconds,
              cpuTime.medianSeconds, tris / cpuTime.minSeconds, cpu.stats.triangulateMs, cpu.stats.evaluateMs);
  std::printf("| Vulkan | %.3f | %.3f | %.3g | %.2f | %.0f, %.0f |\n", gpuTime.minSeconds,
              gpuTime.medianSeconds, tris / gpuTime.minSeconds, cpuTime.minSeconds / gpuTime.minSeconds,
              gpu.stats.triangulateMs, gpu.stats.evaluateMs);
  return 0;
}
