// Final-mesh generation: from finished quad-trees to a watertight indexed mesh — leaf
// triangulation with stitching across patches (CPU), then positions and normals of every
// vertex evaluated in one batch, on Vulkan or on the CPU (the fp32 mirror, all cores) — in
// triangles per second, on the teapot ×N, in one run.
// Usage: bench_mesh [instances=1000] [--json file]
#include <cstdio>
#include <cstdlib>

#include "bench_args.h"
#include "bench_report.h"
#include "bench_scenes.h"
#include "io/bpt_reader.h"
#include "mesh/tessellate.h"
#include "vk/context.h"

using namespace tessera;

int main(int argc, char** argv) {
  bench::Report report("bench_mesh", "[instances=1000] [--json file]", argc, argv);
  bench::atMostArguments(report, argc, argv, 1);
  int instances = argc > 1 ? int(bench::integerArg(report, argv[1], "instances", 1, 100000)) : 1000;
  auto patches = bench::perturbedCopies(readBpt(TESSERA_BENCH_DATA "/teapot.bpt"), instances);
  const PatchSet gpuPatches(toGpuPatches(patches));
  vk::ContextOptions options;
  vk::Context context(options);
  report.setDevice(context);
  Backend vulkan = makeVulkanBackend(context);
  auto cpuEvaluator = makeMirrorEvaluator();

  QuadtreeOptions q;
  q.rule = SplitRule::Midpoint;
  QuadtreeResult tree = buildQuadtree(gpuPatches, q, *vulkan.classifier);

  Tessellation gpu, cpu;
  auto cpuTime = bench::timeRepeated(bench::kMinRuns, [&] {
    cpu = meshFromTree(patches, gpuPatches, tree, *cpuEvaluator);
  });
  auto gpuTime = bench::timeRepeated(bench::kMinRuns, [&] {
    gpu = meshFromTree(patches, gpuPatches, tree, *vulkan.evaluator);
  });
  if (gpu.mesh.indices != cpu.mesh.indices) std::printf("WARNING: the two meshes differ\n");
  char title[200];
  std::snprintf(title, sizeof title,
                "final mesh from rule-B trees at 0.1, teapot x%d (%zu patches, %zu leaves): %zu "
                "triangles, %zu vertices",
                instances, patches.size(), tree.leaves.size(), gpu.mesh.triangleCount(),
                gpu.mesh.vertexCount());
  bench::Table& table = report.table("mesh", "triangles", title);
  const double tris = double(gpu.mesh.triangleCount());
  for (auto [path, timing, t] : {std::make_tuple("vertex evaluation on the CPU (fp32 mirror, all cores)",
                                                 cpuTime, &cpu),
                                 std::make_tuple("vertex evaluation on Vulkan", gpuTime, &gpu)}) {
    bench::Case c{path, tris, timing};
    c.extra = {{"teapots", instances}, {"vertices", t->mesh.vertexCount()},
               {"triangulateMs", t->stats.triangulateMs}, {"evaluateMs", t->stats.evaluateMs}};
    table.cases.push_back(c);
  }
  report.print(table);
  std::printf("\nsplit of the last run: CPU triangulation %.0f ms + evaluation %.0f ms; "
              "Vulkan triangulation %.0f ms + evaluation %.0f ms\n",
              cpu.stats.triangulateMs, cpu.stats.evaluateMs, gpu.stats.triangulateMs,
              gpu.stats.evaluateMs);
  report.finish();
  return 0;
}
