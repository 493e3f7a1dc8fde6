// The largest scene: a wavy sheet tiled into n×n bicubic patches (10⁶ by default) tessellated
// whole on Vulkan with a frontier budget, to show the frontier stays within it whatever the
// scene size (docs/hardening.md). Patches share edges exactly (control points come from one
// lattice), so the mesh is one watertight sheet. A memory figure, not a speed case: one timed
// run (its `runs` is 1), its peak resident memory (getrusage), the frontier's peak, batches
// and patch groups. Exits 1 if the frontier exceeded its budget.
// Usage: bench_scale [patches] [frontier budget MiB] [--json file]
#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "bench_args.h"
#include "bench_report.h"
#include "common/stopwatch.h"
#include "mesh/tessellate.h"
#include "vk/context.h"

using namespace tessera;

namespace {

std::vector<BezierPatch> wavySheet(int n) {
  // Lattice point (I, J) of the 3n+1 × 3n+1 control net; patch (a, b) takes its 4×4 block.
  auto lattice = [n](int i, int j) {
    const double x = double(i) / 3.0, y = double(j) / 3.0;
    return glm::dvec3(x, y, 0.15 * std::sin(1.9 * x) * std::cos(1.3 * y));
  };
  std::vector<BezierPatch> patches;
  patches.reserve(size_t(n) * size_t(n));
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      BezierPatch p;
      p.cp.resize(16);
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) p.at(i, j) = lattice(3 * a + i, 3 * b + j);
      patches.push_back(std::move(p));
    }
  return patches;
}

double peakResidentMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;  // kilobytes on Linux
}

}  // namespace

int main(int argc, char** argv) {
  bench::Report report("bench_scale", "[patches=1000000] [frontier budget MiB=64] [--json file]",
                       argc, argv);
  bench::atMostArguments(report, argc, argv, 2);
  const long requested =
      argc > 1 ? bench::integerArg(report, argv[1], "patches", 1, 100000000) : 1000000;
  const double budgetMiB =
      argc > 2 ? bench::numberArg(report, argv[2], "frontier budget MiB", 1.0 / 1024) : 64.0;
  const int n = std::max(1, int(std::lround(std::sqrt(double(requested)))));
  auto patches = wavySheet(n);
  const double sceneMiB = peakResidentMiB();

  vk::Context context;
  report.setDevice(context);
  Backend vulkan = makeVulkanBackend(context);
  QuadtreeOptions options;
  options.rule = SplitRule::Midpoint;
  options.linearity = options.flatness = 0.02f;
  options.frontierBudgetBytes = size_t(budgetMiB * 1024 * 1024);
  const Stopwatch stopwatch;
  Tessellation t = tessellate(patches, options, vulkan);
  const double seconds = stopwatch.elapsedSeconds();

  const QuadtreeResult& tree = t.tree;
  const size_t batchNodes = frontierBatchNodes(options, vulkan.classifier->maxBatchNodes());
  const double frontierMiB =
      double(tree.peakFrontierNodes * kFrontierBytesPerNode + batchNodes * sizeof(gpu::NodeDecision)) /
      (1024.0 * 1024.0);
  char title[160];
  std::snprintf(title, sizeof title, "%zu patches (%dx%d wavy sheet), rule B at 0.02, frontier budget %.0f MiB, one run",
                patches.size(), n, n, budgetMiB);
  bench::Table& table = report.table("scale", "triangles", title);
  bench::Case c;
  c.path = "Vulkan (" + context.info().name + "), batched frontier";
  c.workSize = double(t.stats.triangles);
  c.timing = {seconds, seconds, 1};
  c.throughput = double(t.stats.triangles) / seconds;
  c.extra = {{"patches", patches.size()},          {"leaves", tree.leaves.size()},
             {"patchGroups", tree.patchGroups},    {"batches", tree.batches},
             {"batchNodes", batchNodes},           {"peakFrontierMiB", frontierMiB},
             {"frontierBudgetMiB", budgetMiB},     {"sceneMiB", sceneMiB},
             {"peakResidentMiB", peakResidentMiB()}};
  table.cases.push_back(c);
  report.print(table);
  std::printf("| patches | leaves | triangles | patch groups | batches | batch nodes | peak frontier MiB | budget MiB | scene MiB | peak RSS MiB | seconds |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::printf("| %zu | %zu | %zu | %zu | %zu | %zu | %.1f | %.1f | %.0f | %.0f | %.1f |\n",
              patches.size(), tree.leaves.size(), t.stats.triangles, tree.patchGroups,
              tree.batches, batchNodes, frontierMiB, budgetMiB, sceneMiB, peakResidentMiB(),
              seconds);
  report.finish();
  if (frontierMiB > budgetMiB) {
    std::printf("FAILED: the frontier exceeded its budget\n");
    return 1;
  }
  return 0;
}
