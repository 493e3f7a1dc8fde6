// Case 2, adaptive quad-tree throughput: leaves per second for the scalar CPU (the fp32 mirror
// on one thread), the CPU on all cores, and Vulkan, on the same perturbed teapots, in one run;
// then where the Vulkan run's time goes, level by level (GPU, readback, CPU frontier work).
// Usage: bench_quadtree [instancesB=1000] [instancesD=100] [threshold=0.05] [--json file]
// (rule D costs ~300 κ evaluations per node: the rate per leaf is what is compared).
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "bench_args.h"
#include "bench_report.h"
#include "bench_scenes.h"
#include "eval/evaluator.h"
#include "io/bpt_reader.h"
#include "quadtree/quadtree.h"
#include "vk/context.h"

using namespace tessera;

namespace {

void benchRule(bench::Report& report, SplitRule rule, int instances, float threshold,
               const std::vector<BezierPatch>& teapot, vk::Context& context) {
  auto patches = toGpuPatches(bench::perturbedCopies(teapot, instances));
  QuadtreeOptions o;
  o.rule = rule;
  o.linearity = o.flatness = threshold;
  o.timeGpu = true;  // the levels' GPU ms are reported
  auto scalar = makeMirrorClassifier();
  auto parallel = makeParallelMirrorClassifier();
  auto vulkan = makeVulkanClassifier(context);

  QuadtreeResult results[3];
  NodeClassifier* classifiers[3] = {scalar.get(), parallel.get(), vulkan.get()};
  std::string paths[3] = {
      "scalar CPU (fp32 mirror, 1 thread)",
      "CPU, all " + std::to_string(std::thread::hardware_concurrency()) + " cores",
      "Vulkan (" + context.info().name + ")"};
  char title[200];
  std::snprintf(title, sizeof title,
                "quad-tree rule %c, linearity = flatness = %.2f, teapot x%d (%zu patches)",
                splitRuleLetter(rule), threshold, instances, patches.size());
  bench::Table& table =
      report.table(std::string("quad-tree ") + splitRuleLetter(rule), "leaves", title);
  for (int k = 0; k < 3; ++k) {
    bench::Case c{paths[k], 0};
    c.timing = bench::timeRepeated(bench::kMinRuns, [&] {
      results[k] = buildQuadtree(patches, o, *classifiers[k]);
    });
    c.workSize = double(results[k].leaves.size());
    c.extra = {{"teapots", instances}, {"patches", patches.size()},
               {"depth", results[k].depth}};
    table.cases.push_back(c);
  }
  if (results[0].leaves.size() != results[2].leaves.size() ||
      results[1].leaves.size() != results[2].leaves.size())
    std::printf("WARNING: leaf counts differ: scalar %zu, parallel %zu, vulkan %zu\n",
                results[0].leaves.size(), results[1].leaves.size(), results[2].leaves.size());
  nlohmann::json levels = nlohmann::json::array();
  for (const LevelStats& l : results[2].levels)
    levels.push_back({{"level", l.level}, {"nodes", l.nodes}, {"splits", l.splits},
                      {"leaves", l.leaves}, {"classifyMs", l.classifyMs}, {"gpuMs", l.gpuMs},
                      {"frontierMs", l.frontierMs}});
  table.cases[2].extra["levels"] = levels;
  report.print(table);
  std::printf("\nVulkan run by level (classify = upload + dispatch + readback; GPU = timestamps; "
              "frontier = host work on leaves and children):\n\n");
  std::printf("| level | nodes | splits | leaves | classify ms | GPU ms | frontier ms |\n"
              "|---|---|---|---|---|---|---|\n");
  for (const LevelStats& l : results[2].levels)
    std::printf("| %u | %zu | %zu | %zu | %.1f | %.1f | %.1f |\n", l.level, l.nodes, l.splits,
                l.leaves, l.classifyMs, l.gpuMs, l.frontierMs);
}

}  // namespace

int main(int argc, char** argv) {
  bench::Report report("bench_quadtree",
                       "[instancesB=1000] [instancesD=100] [threshold=0.05] [--json file]", argc,
                       argv);
  bench::atMostArguments(report, argc, argv, 3);
  int instancesB =
      argc > 1 ? int(bench::integerArg(report, argv[1], "instancesB", 0, 100000)) : 1000;
  int instancesD =
      argc > 2 ? int(bench::integerArg(report, argv[2], "instancesD", 0, 100000)) : 100;
  float threshold = argc > 3 ? float(bench::numberArg(report, argv[3], "threshold", 0)) : 0.05f;
  auto teapot = readBpt(TESSERA_BENCH_DATA "/teapot.bpt");
  vk::ContextOptions options;
  vk::Context context(options);
  report.setDevice(context);
  if (instancesB > 0) benchRule(report, SplitRule::Midpoint, instancesB, threshold, teapot, context);
  if (instancesD > 0) benchRule(report, SplitRule::TrueMax, instancesD, threshold, teapot, context);
  report.finish();
  return 0;
}
