// Rule T's quad-tree alone (issue 15), on the tea set as bench_occt builds it: per level, the
// minimum over runs of the GPU time, the rest of the classify call and the frontier time, and
// the tree's total, for one classifier. Small enough to run under callgrind or perf stat.
// Usage: bench_tree_levels [tolerances=0.01,0.001] [runs=20] [vulkan|mirror] [host level
// nodes=kHostLevelNodes] (text output only: scripts/bench.sh's --json <file> is accepted and
// ignored). vulkan is makeVulkanBackend's classifier: levels of fewer nodes than the fourth
// argument on the host's mirror (0: every level on the device).
#include <algorithm>
#include <cstdlib>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_args.h"
#include "bench_report.h"
#include "common/stopwatch.h"
#include "eval/patch_set.h"
#include "geometry/model_frame.h"
#include "io/bpt_reader.h"
#include "quadtree/quadtree.h"
#include "vk/context.h"

using namespace tessera;

// Where a level was decided: "host" (the mirror, all of it), "device", "fused" (the device,
// all of it by rule T's fused dispatch), or "both" (batches).
const char* placeOf(const LevelStats& level, const std::string& which) {
  if (which == "mirror" || level.hostNodes == level.nodes) return "host";
  if (level.hostNodes != 0) return "both";
  return level.fusedNodes == level.nodes ? "fused" : "device";
}

int main(int argc, char** argv) {
  // Its report is never written (text only): Report checks the arguments and takes --json.
  bench::Report report("bench_tree_levels",
                       "[tolerances=0.01,0.001] [runs=20] [vulkan|mirror] [host level nodes=64]",
                       argc, argv);
  bench::atMostArguments(report, argc, argv, 4);
  std::vector<double> tolerances = {0.01, 0.001};
  if (argc > 1) tolerances = bench::numberListArg(report, argv[1], "tolerances", 1e-9);
  const int runs = argc > 2 ? int(bench::integerArg(report, argv[2], "runs", 1, 100000)) : 20;
  const std::string which = argc > 3 ? argv[3] : "vulkan";
  if (which != "vulkan" && which != "mirror")
    report.usageError("classifier '" + which + "': expected vulkan or mirror");
  const size_t hostLevelNodes =
      argc > 4 ? size_t(bench::integerArg(report, argv[4], "host level nodes", 0, 1L << 30))
               : kHostLevelNodes;

  std::vector<BezierPatch> patches;
  const char* names[] = {"teapot", "teacup", "teaspoon"};
  for (int k = 0; k < 3; ++k) {
    auto model = readBpt(std::string(TESSERA_BENCH_DATA "/") + names[k] + ".bpt");
    for (auto& p : model) {
      for (auto& c : p.cp) c.x += 10.0 * double(k);  // as bench_occt places them
      patches.push_back(p);
    }
  }
  const ModelFrame frame = modelFrame(patches);
  const PatchSet set = toPatchSet(toLocalFrame(patches, frame));

  vk::ContextOptions contextOptions;
  vk::Context context(contextOptions);
  auto classifier = which == "mirror"
                        ? makeParallelMirrorClassifier()
                        : withSmallLevelsOnHost(makeVulkanClassifier(context), hostLevelNodes);
  std::printf("classifier %s, levels of < %zu nodes on the host\n", classifier->name().c_str(),
              which == "mirror" ? size_t(0) : hostLevelNodes);

  for (double tolerance : tolerances) {
    QuadtreeOptions options = toleranceOptions(tolerance / frame.scale);
    options.timeGpu = true;  // the levels' GPU ms are the table's first column
    std::vector<LevelStats> best;
    double bestTotal = 1e30;
    size_t leaves = 0;
    for (int run = 0; run < runs; ++run) {
      const Stopwatch stopwatch;
      QuadtreeResult tree = buildQuadtree(set, options, *classifier);
      bestTotal = std::min(bestTotal, stopwatch.elapsedMs());
      leaves = tree.leaves.size();
      if (best.empty()) best = tree.levels;
      for (size_t l = 0; l < tree.levels.size() && l < best.size(); ++l) {
        best[l].gpuMs = std::min(best[l].gpuMs, tree.levels[l].gpuMs);
        best[l].classifyMs = std::min(best[l].classifyMs, tree.levels[l].classifyMs);
        best[l].frontierMs = std::min(best[l].frontierMs, tree.levels[l].frontierMs);
        best[l].fusedNodes = tree.levels[l].fusedNodes;  // "on": the last run's dispatches
      }
    }
    std::printf("δ %g: %zu leaves, tree min %.3f ms over %d runs\n", tolerance, leaves, bestTotal,
                runs);
    std::printf("| level | nodes | splits | on | GPU ms | classify ms | frontier ms |\n");
    double gpu = 0, classify = 0, frontier = 0;
    for (const LevelStats& l : best) {
      std::printf("| %u | %zu | %zu | %s | %.3f | %.3f | %.3f |\n", l.level, l.nodes, l.splits,
                  placeOf(l, which), l.gpuMs, l.classifyMs, l.frontierMs);
      gpu += l.gpuMs, classify += l.classifyMs, frontier += l.frontierMs;
    }
    std::printf("| sum of minima | | | | %.3f | %.3f | %.3f |\n", gpu, classify, frontier);
  }
  return 0;
}
