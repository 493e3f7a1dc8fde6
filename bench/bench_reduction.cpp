// Control-point reduction (docs/reduction.md), one run each, as the issue asks:
// 1. the whole reduction of the synthetic last (default 1,500 × 1,500 = 2.25M control points)
//    at 0.01 mm with curvature-chosen knots (the default, re-ranked choice), CPU-only vs with the row product on Vulkan;
// 2. one dense curve of it (a heel-to-toe line) reduced by our inverse Oslo (threshold on the
//    max error) and by SISL's data reduction s1940 ("remove as many knots as possible without
//    perturbing the curve more than eps", Lyche–Mørken knot removal) at the same tolerance:
//    control points kept, time, and the sampled deviation of each from the dense curve.
// Usage: bench_reduction [--count N] [--json FILE]
#include <sisl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include "bench_args.h"
#include "bench_report.h"
#include "common/stopwatch.h"
#include "reduction/curve_product.h"
#include "reduction/fast.h"
#include "experiments/synthetic_surfaces.h"
#include "vk/context.h"

using namespace tessera;

namespace {

double secondsOf(const std::function<void()>& work) {
  const Stopwatch stopwatch;
  work();
  return stopwatch.elapsedSeconds();
}

// Largest distance between two curves on the same domain, sampled at 20,000 parameters.
double sampledDeviation(const BSplineCurve& a, const BSplineCurve& b) {
  const double t0 = a.knots[static_cast<size_t>(a.degree)], t1 = a.knots[a.cp.size()];
  double worst = 0.0;
  for (int k = 0; k <= 20000; ++k) {
    const double t = t0 + (t1 - t0) * k / 20000.0;
    worst = std::max(worst, glm::length(curvePoint(a, t) - curvePoint(b, t)));
  }
  return worst;
}

// Our reduction of one curve: a surface of 4 identical rows (the minimum for cubic in u, so the
// u pass has nothing to remove) reduced along v with the whole threshold on the max error.
BSplineCurve reduceCurveOurs(const BSplineCurve& c, double tolerance) {
  BSplineSurface s;
  s.countU = 4;
  s.countV = static_cast<int>(c.cp.size());
  s.knotsU = {0, 0, 0, 0, 1, 1, 1, 1};
  s.knotsV = c.knots;
  for (int i = 0; i < 4; ++i) s.cp.insert(s.cp.end(), c.cp.begin(), c.cp.end());
  ReductionOptions o;
  o.threshold = tolerance;
  o.measure = ErrorMeasure::Max;
  o.firstPassShare = 1.0;
  const ReductionResult r = reduceSurface(s, o);
  BSplineCurve out{3, r.surface.knotsV, {}};
  out.cp.assign(r.surface.cp.begin(), r.surface.cp.begin() + r.surface.countV);
  return out;
}

// SISL s1940 with eps per coordinate = tolerance / √3, so that its Euclidean error is also
// within the tolerance; no derivatives fixed at the ends; open curve; up to 10 iterations.
BSplineCurve reduceCurveSisl(const BSplineCurve& c, double tolerance) {
  std::vector<double> coef;
  for (const glm::dvec3& q : c.cp) coef.insert(coef.end(), {q.x, q.y, q.z});
  std::vector<double> knots = c.knots;
  SISLCurve* in = newCurve(static_cast<int>(c.cp.size()), c.degree + 1, knots.data(), coef.data(),
                           1, 3, 1);
  double eps[3] = {tolerance / std::sqrt(3.0), tolerance / std::sqrt(3.0), tolerance / std::sqrt(3.0)};
  double maxerr[3] = {0, 0, 0};
  SISLCurve* out = nullptr;
  int stat = 0;
  s1940(in, eps, 0, 0, 1, 10, &out, maxerr, &stat);
  freeCurve(in);
  if (stat < 0 || out == nullptr) throw std::runtime_error("SISL s1940 failed, stat " + std::to_string(stat));
  BSplineCurve result{out->ik - 1, std::vector<double>(out->et, out->et + out->in + out->ik), {}};
  for (int i = 0; i < out->in; ++i) result.cp.push_back({out->ecoef[3 * i], out->ecoef[3 * i + 1], out->ecoef[3 * i + 2]});
  freeCurve(out);
  return result;
}

}  // namespace

int main(int argc, char** argv) {
  bench::Report report("bench_reduction", "[--count N] [--json file]", argc, argv);
  int count = kLargeSurfaceCount;
  for (int a = 1; a < argc; ++a) {
    if (std::strcmp(argv[a], "--count") == 0 && a + 1 < argc)
      count = int(bench::integerArg(report, argv[++a], "--count", 4, 100000));
    else
      report.usageError(std::string("unexpected argument '") + argv[a] + "'");
  }
  const BSplineSurface surface = syntheticLast(count, count);
  ReductionOptions options;
  options.threshold = 0.01;

  bench::Table& whole = report.table(
      "reduction", "control points",
      "Whole reduction of the " + std::to_string(count) + "² synthetic last at 0.01 mm "
      "(curvature-chosen knots), one run each; throughput = original control points per second");
  ReductionResult cpuResult, gpuResult;
  FastPathStats cpuStats;
  const double cpuSeconds =
      secondsOf([&] { cpuResult = reduceSurface(surface, options, nullptr, &cpuStats); });
  bench::Case cpuCase{"CPU only (double)", double(surface.cp.size()), {cpuSeconds, cpuSeconds, 1}};
  // The window solves' locality and their drift from the from-scratch fit (docs/reduction.md).
  const double drift = std::max(cpuStats.drift[0], cpuStats.drift[1]);
  cpuCase.extra = {{"kept", cpuResult.keptControlPoints},
                   {"ratioPercent", cpuResult.compressionPercent()},
                   {"widestWindow", cpuStats.widestWindow}, {"drift", drift}};
  std::printf("CPU only: kept %lld (%.3f %%), widest window %d, drift %.3g mm\n",
              cpuResult.keptControlPoints, cpuResult.compressionPercent(), cpuStats.widestWindow,
              drift);
  whole.cases.push_back(cpuCase);
  try {
    vk::Context context;
    report.setDevice(context);
    auto product = makeVulkanCurveProduct(context);
    FastPathStats stats;
    const double gpuSeconds = secondsOf([&] { gpuResult = reduceSurface(surface, options, product.get(), &stats); });
    bench::Case gpuCase{"row product on Vulkan (fp32)", double(surface.cp.size()), {gpuSeconds, gpuSeconds, 1}};
    gpuCase.extra = {{"kept", gpuResult.keptControlPoints},
                     {"productSeconds", stats.productSeconds[0] + stats.productSeconds[1]},
                     {"searchSeconds", stats.searchSeconds[0] + stats.searchSeconds[1]}};
    whole.cases.push_back(gpuCase);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_reduction: no Vulkan case (%s)\n", e.what());
  }
  report.print(whole);

  // The curve: the heel-to-toe line along the top of the last (u = 1/4 of the way round).
  BSplineCurve curve{3, surface.knotsV, {}};
  const int row = count / 4;
  curve.cp.assign(surface.cp.begin() + static_cast<long>(row) * count,
                  surface.cp.begin() + static_cast<long>(row + 1) * count);
  bench::Table& curves = report.table(
      "curve", "control points",
      "One " + std::to_string(count) + "-point curve of the last, reduced at the same tolerance "
      "(max Euclidean error; SISL eps = tol/sqrt(3) per coordinate), one run each");
  for (double tolerance : {0.01, 0.05}) {
    BSplineCurve ours, sisl;
    const double oursSeconds = secondsOf([&] { ours = reduceCurveOurs(curve, tolerance); });
    const double sislSeconds = secondsOf([&] { sisl = reduceCurveSisl(curve, tolerance); });
    for (int k = 0; k < 2; ++k) {
      const BSplineCurve& c = k == 0 ? ours : sisl;
      const double seconds = k == 0 ? oursSeconds : sislSeconds;
      bench::Case cs{std::string(k == 0 ? "inverse Oslo (ours)" : "SISL s1940") + " at " +
                         std::to_string(tolerance).substr(0, 4) + " mm",
                     double(curve.cp.size()), {seconds, seconds, 1}};
      cs.extra = {{"kept", c.cp.size()}, {"sampledMaxDeviation", sampledDeviation(curve, c)}};
      curves.cases.push_back(cs);
      std::printf("%-28s kept %5zu of %zu control points, sampled max deviation %.4g mm, %.4f s\n",
                  cs.path.c_str(), c.cp.size(), curve.cp.size(), sampledDeviation(curve, c), seconds);
    }
  }
  report.print(curves);
  report.finish();
  return 0;
}
