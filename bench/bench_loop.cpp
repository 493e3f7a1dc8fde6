// Loop subdivision (issue 7, case 4), in one run:
// 1. refinement of a ~10k-triangle control mesh to level 4 (every level's vertices): our stencil
//    tables applied on Vulkan (chained: one dispatch per level; factorized: one dispatch), by our
//    CPU (double, and the fp32 mirror), and by OpenSubdiv's CPU evaluator
//    (Osd::CpuEvaluator::EvalStencils on Far's factorized stencil table for the same levels);
//    table building timed apart;
// 2. joining two ~10k-triangle closed meshes: the interference test with our BVH against the
//    paper's all-pairs test (run fewer times: it is slow), and the whole join.
// Usage: bench_loop [frequency=22] [--json file]
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/osd/cpuEvaluator.h>

#include <cstdio>
#include <cstdlib>

#include "bench_args.h"
#include "bench_report.h"
#include "common/stopwatch.h"
#include "loop/bvh.h"
#include "loop/evaluator.h"
#include "loop/join.h"
#include "loop/shapes.h"
#include "loop/stencils.h"
#include "osd/osd_loop.h"
#include "vk/context.h"

using namespace tessera;
using namespace OpenSubdiv;

namespace {

constexpr int kLevels = 4;

std::vector<float> controlRows(const LoopShape& s, size_t rows) {
  std::vector<float> out(rows * 3, 0.0f);
  for (size_t v = 0; v < s.positions.size(); ++v)
    for (int c = 0; c < 3; ++c) out[3 * v + c] = float(s.positions[v][c]);
  return out;
}

void refinementTable(bench::Report& report, vk::Context& context, const LoopShape& shape) {
  const LoopTopology base = buildLoopTopology(shape.topology);
  LoopStencilOptions chainedOptions, factorizedOptions;
  chainedOptions.levels = factorizedOptions.levels = kLevels;
  factorizedOptions.factorize = true;
  LoopStencils chained, factorized;
  const auto buildChained = bench::timeRepeated(1, [&] { chained = buildLoopStencils(base, chainedOptions); });
  const auto buildFactorized = bench::timeRepeated(1, [&] { factorized = buildLoopStencils(base, factorizedOptions); });
  const FloatStencilTable chainedF = toFloatStencils(chained.table), factorizedF = toFloatStencils(factorized.table);
  const double refined = double(chained.table.stencilCount());

  // OpenSubdiv: Far's stencil table for levels 1..4 (factorized, its default), applied by
  // Osd::CpuEvaluator from the control rows.
  Far::StencilTable const* osdTable = nullptr;
  const auto buildOsd = bench::timeRepeated(1, [&] {
    auto refiner = osd::makeLoopRefiner(shape.topology);
    refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(kLevels));
    Far::StencilTableFactory::Options options;
    options.generateOffsets = true;
    options.generateIntermediateLevels = true;
    delete osdTable;
    osdTable = Far::StencilTableFactory::Create(*refiner, options);
  });
  std::vector<float> osdSrc = controlRows(shape, shape.positions.size());
  std::vector<float> osdDst(size_t(osdTable->GetNumStencils()) * 3);
  const Osd::BufferDescriptor desc(0, 3, 3);

  auto cpu = makeReferenceStencilEvaluator(chained.table, 3);
  auto mirror = makeMirrorStencilEvaluator(chainedF, 3);
  VulkanStencilOptions timed;
  timed.timeGpu = true;  // the device times below
  auto gpuChained = makeVulkanStencilEvaluator(context, chainedF, 3, timed);
  auto gpuFactorized = makeVulkanStencilEvaluator(context, factorizedF, 3, timed);
  std::vector<float> rows = controlRows(shape, chained.table.rowCount());
  double gpuChainedDevice = 0, gpuFactorizedDevice = 0;
  struct Path { const char* name; std::function<void()> run; };
  const std::vector<Path> paths = {
      {"our CPU, double (chained table)", [&] { cpu->apply(rows); }},
      {"our CPU, fp32 mirror (chained table)", [&] { mirror->apply(rows); }},
      {"OpenSubdiv Osd::CpuEvaluator (Far factorized table)", [&] {
         Osd::CpuEvaluator::EvalStencils(osdSrc.data(), desc, osdDst.data(), desc,
                                         &osdTable->GetSizes()[0], &osdTable->GetOffsets()[0],
                                         &osdTable->GetControlIndices()[0], &osdTable->GetWeights()[0],
                                         0, osdTable->GetNumStencils());
       }},
      {"Vulkan, chained (one dispatch per level)", [&] { gpuChained->apply(rows); gpuChainedDevice = gpuChained->lastDeviceSeconds(); }},
      {"Vulkan, factorized (one dispatch)", [&] { gpuFactorized->apply(rows); gpuFactorizedDevice = gpuFactorized->lastDeviceSeconds(); }},
  };
  char title[256];
  std::snprintf(title, sizeof title,
                "Loop refinement of %s (%zu triangles) to level %d: %.0f refined vertices (all "
                "levels), %zu triangles at level %d; including upload and readback",
                shape.name.c_str(), shape.topology.triangles.size() / 3, kLevels, refined,
                chained.topology.back().faceCount(), kLevels);
  bench::Table& table = report.table("loop refinement", "vertices", title);
  for (const Path& p : paths) {
    bench::Case c{p.name, refined, bench::timeRepeated(bench::kMinRuns, p.run)};
    table.cases.push_back(c);
  }
  table.cases[3].extra = {{"deviceSeconds", gpuChainedDevice}};
  table.cases[4].extra = {{"deviceSeconds", gpuFactorizedDevice}};
  report.print(table);
  std::printf("\ntable building (CPU, once): ours chained %.3f s (%zu entries), ours factorized "
              "%.3f s (%zu entries), OpenSubdiv Far %.3f s (%zu entries); Vulkan device time "
              "of the last run: chained %.1f ms, factorized %.1f ms\n",
              buildChained.minSeconds, chained.table.indices.size(), buildFactorized.minSeconds,
              factorized.table.indices.size(), buildOsd.minSeconds,
              osdTable->GetControlIndices().size(), 1e3 * gpuChainedDevice, 1e3 * gpuFactorizedDevice);
  delete osdTable;
}

void joinTable(bench::Report& report, int frequency) {
  LoopShape torus = loopTorus(100, 50, 0.0, 1);
  LoopShape ball = loopIcosphere(frequency);
  for (auto& p : ball.positions) p = 0.4 * p + glm::dvec3(1.5, 0, 0);
  const TriangleBvh a(ball.positions, ball.topology.triangles);
  const TriangleBvh b(torus.positions, torus.topology.triangles);
  size_t fastPairs = 0, slowPairs = 0;
  TriangleBvh* built = nullptr;
  const auto buildTime = bench::timeRepeated(bench::kMinRuns, [&] {
    delete built;
    built = new TriangleBvh(torus.positions, torus.topology.triangles);
  });
  delete built;
  const auto fast = bench::timeRepeated(bench::kMinRuns, [&] {
    fastPairs = 0;
    a.forEachIntersecting(b, [&](uint32_t, uint32_t) { ++fastPairs; });
  });
  // All pairs: 1e8 triangle tests; timed once (after no warm-up) to keep the run short.
  const Stopwatch stopwatch;
  forEachIntersectingBruteForce(a, b, [&](uint32_t, uint32_t) { ++slowPairs; });
  const double slowSeconds = stopwatch.elapsedSeconds();
  LoopJoinResult joined;
  const auto whole = bench::timeRepeated(bench::kMinRuns, [&] { joined = joinLoopMeshes(ball, torus); });
  const double pairs = double(a.triangleCount()) * double(b.triangleCount());
  char title[256];
  std::snprintf(title, sizeof title,
                "joining a ball (%zu triangles) into a torus (%zu): %zu intersecting pairs (BVH) "
                "vs %zu (all pairs); work = candidate pairs",
                a.triangleCount(), b.triangleCount(), fastPairs, slowPairs);
  bench::Table& table = report.table("loop join", "pairs", title);
  table.cases.push_back({"interference, all pairs (the paper's method), 1 run", pairs, {slowSeconds, slowSeconds, 1}});
  table.cases.push_back({"interference, BVH (built once per mesh)", pairs, fast});
  table.cases.push_back({"BVH build of one 10k-triangle mesh", pairs, buildTime});
  table.cases.push_back({"whole join with BVH (refine, remove, bridge, fit)", pairs, whole});
  table.cases.back().extra = {{"trianglesIn", joined.report.trianglesIn},
                              {"trianglesOut", joined.report.trianglesOut},
                              {"fittedVertices", joined.report.fittedVertices},
                              {"maxDeviation", joined.report.maxDeviation}};
  report.print(table);
  if (fastPairs != slowPairs) std::printf("WARNING: BVH and all-pairs disagree\n");
  std::printf("\njoin: %zu -> %zu triangles, %zu fitted vertices, max |p_inf - original| %.2e\n",
              joined.report.trianglesIn, joined.report.trianglesOut,
              joined.report.fittedVertices, joined.report.maxDeviation);
}

}  // namespace

int main(int argc, char** argv) {
  bench::Report report("bench_loop", "[frequency=22] [--json file]", argc, argv);
  bench::atMostArguments(report, argc, argv, 1);
  // 20·f² triangles: 9680
  const int frequency =
      argc > 1 ? int(bench::integerArg(report, argv[1], "frequency", 1, 200)) : 22;
  vk::ContextOptions options;
  vk::Context context(options);
  report.setDevice(context);
  refinementTable(report, context, loopBunny(frequency, 1));
  joinTable(report, frequency);
  report.finish();
  return 0;
}
