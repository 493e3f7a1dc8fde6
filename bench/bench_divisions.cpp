// Division counts per second for rational Bézier patches (the split method,
// docs/rational_division.md): scalar CPU (the double reference, and the fp32 mirror, one
// thread each) vs Vulkan (upload + dispatch + readback), on the same patches in one run.
// Biquadratic patches (the rational cylinders and tori of the paper), a quarter each with all
// weights positive, zero interior weights, negative interior weights, and both (all negative
// with zeros). Usage: bench_divisions [patches] [--json file]
#include <cstdio>
#include <algorithm>
#include <cstdlib>
#include <random>

#include "bench_common.h"
#include "bench_args.h"
#include "bench_report.h"
#include "division/count.h"
#include "division/counter.h"
#include "vk/context.h"

using namespace tessera;

namespace {

RationalBezierPatch randomPatch(int kind, std::mt19937& rng) {
  std::uniform_real_distribution<double> coord(-1.0, 1.0), weight(0.3, 2.0), unit(0.0, 1.0);
  RationalBezierPatch p;
  p.degreeU = p.degreeV = 2;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const bool corner = (i != 1) && (j != 1);
      double w = weight(rng);
      if (!corner && (kind == 1 || kind == 3) && unit(rng) < 0.4) w = 0.0;
      if (!corner && kind == 2 && unit(rng) < 0.25) w = -0.3 * unit(rng);
      if (kind == 3) w = -w;
      const glm::dvec3 x(i + 0.3 * coord(rng), j + 0.3 * coord(rng), coord(rng));
      p.cpw.push_back(w == 0.0 ? glm::dvec4(x, 0.0) : glm::dvec4(w * x, w));
    }
  return p;
}

}  // namespace

int main(int argc, char** argv) {
  bench::Report report("bench_divisions", "[patches=1048576] [--json file]", argc, argv);
  bench::atMostArguments(report, argc, argv, 1);
  const size_t count = argc > 1 ? size_t(bench::integerArg(report, argv[1], "patches", 1, 1L << 26))
                                : size_t(1) << 20;
  std::mt19937 rng(11);
  std::vector<RationalBezierPatch> patches;
  patches.reserve(count);
  for (size_t k = 0; k < count; ++k) patches.push_back(randomPatch(int(k % 4), rng));
  // Batches of 2^18 patches keep every buffer under lavapipe's 128 MiB storage-buffer range.
  const size_t batchSize = size_t(1) << 18;
  std::vector<DivisionBatch> batches;
  for (size_t first = 0; first < count; first += batchSize)
    batches.push_back(packDivisionBatch(std::vector<RationalBezierPatch>(
        patches.begin() + first, patches.begin() + std::min(count, first + batchSize))));
  DivisionOptions options;
  options.tolerance = 0.01;

  vk::ContextOptions contextOptions;
  vk::Context context(contextOptions);
  report.setDevice(context);
  auto gpu = makeVulkanDivisionCounter(context);
  auto mirror = makeMirrorDivisionCounter();

  long long sink = 0;
  // timeRepeated warms up first (pipeline compilation, buffer allocation, page faults).
  const auto gpuTime = bench::timeRepeated(5, [&] {
    for (const DivisionBatch& b : batches) sink += gpu->count(b, options).back().nu;
  });
  const auto mirrorTime = bench::timeRepeated(5, [&] {
    for (const DivisionBatch& b : batches) sink += mirror->count(b, options).back().nu;
  });
  const auto doubleTime = bench::timeRepeated(5, [&] {
    for (const RationalBezierPatch& p : patches) sink += patchDivisions(p, options).nu;
  });

  char title[200];
  std::snprintf(title, sizeof title,
                "%zu biquadratic rational patches (1/4 each: positive, zero, negative, "
                "all-negative-with-zero weights), split method, TOL %.3g",
                count, options.tolerance);
  bench::Table& table = report.table("division counts", "patches", title);
  for (const auto& [path, timing] :
       {std::pair<const char*, bench::Timing>{"scalar CPU (double reference, 1 thread)", doubleTime},
        {"scalar CPU (fp32 mirror, 1 thread)", mirrorTime},
        {"Vulkan (upload + dispatch + readback)", gpuTime}}) {
    bench::Case c;
    c.path = path;
    c.workSize = double(count);
    c.timing = timing;
    table.cases.push_back(c);
  }
  report.print(table);
  report.finish();
  return sink == -1 ? 1 : 0;  // keeps the loops from being optimised away
}
