// The fast path of the control-point reduction (banded_oslo.h, reduction_fast.h) against the
// SVD specification (knot_removal.h): the same least-squares fits to 1e-9, the same decisions,
// and the thresholds respected where the specification is too slow to run.
#include <catch2/catch.hpp>

#include <map>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "reduction/banded_oslo.h"
#include "reduction/curve_product.h"
#include "reduction/knot_removal.h"
#include "bspline/knots.h"
#include "reduction/fast.h"
#include "experiments/synthetic_surfaces.h"

using namespace tessera;

namespace {

double maxCoordinateDiff(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
  REQUIRE(a.size() == b.size());
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(a[i][c] - b[i][c]));
  }
  return worst;
}

// Every reported number of two reductions of the same surface agree: the decisions exactly,
// the nets and errors to `tolerance`.
void requireSameReduction(const ReductionResult& fast, const ReductionResult& spec, double tolerance) {
  for (int pass = 0; pass < 2; ++pass) {
    INFO("pass " << pass);
    CHECK(fast.passes[pass].removed == spec.passes[pass].removed);
    CHECK(fast.passes[pass].refused == spec.passes[pass].refused);
    CHECK(fast.passes[pass].stop == spec.passes[pass].stop);
    CHECK(fast.passes[pass].error.mean == Approx(spec.passes[pass].error.mean).margin(tolerance));
    CHECK(fast.passes[pass].error.max == Approx(spec.passes[pass].error.max).margin(tolerance));
    if (spec.passes[pass].stop == StopReason::Threshold) {
      CHECK(fast.passes[pass].refusedError == Approx(spec.passes[pass].refusedError).margin(tolerance));
    }
  }
  REQUIRE(fast.surface.knotsU == spec.surface.knotsU);
  REQUIRE(fast.surface.knotsV == spec.surface.knotsV);
  const double diff = maxCoordinateDiff(fast.surface.cp, spec.surface.cp);
  WARN("fast vs SVD: " << fast.surface.countU << " x " << fast.surface.countV
                       << " kept, largest coordinate difference " << diff);
  CHECK(diff <= tolerance);
}

}  // namespace

TEST_CASE("Banded least squares matches the SVD pseudo-inverse to 1e-9", "[reduce]") {
  // A dense curve of 160 control points, coordinates up to ~100 (millimetres), reduced to
  // random subsets of its knots, down to the Bézier case.
  const int fine = 160;
  const std::vector<double> y = openUniformKnots(3, fine, 0.0, 1.0);
  std::vector<glm::dvec3> cp;
  for (int j = 0; j < fine; ++j) {
    const double t = j / (fine - 1.0);
    cp.push_back({100.0 * std::cos(6.0 * t), 80.0 * std::sin(9.0 * t) + 3.0 * std::sin(80.0 * t), 50.0 * t * t});
  }
  std::mt19937 rng(11);
  for (int keep : {150, 80, 20, 5, 0}) {
    std::vector<int> interior;
    for (int k = 4; k < fine; ++k) interior.push_back(k);
    std::shuffle(interior.begin(), interior.end(), rng);
    interior.resize(static_cast<size_t>(keep));
    std::sort(interior.begin(), interior.end());
    std::vector<double> x(4, 0.0);
    for (int k : interior) x.push_back(y[static_cast<size_t>(k)]);
    x.insert(x.end(), 4, 1.0);
    const auto svd = inverseOslo(3, x, y, cp);
    const auto band = inverseOsloBanded(3, x, y, cp);
    INFO(keep << " interior knots kept");
    CHECK(maxCoordinateDiff(svd, band) <= 1e-9);
    // A⁺ as a band applied in double: the route the GPU takes.
    const BandMatrix a = osloBand(3, x, y);
    const auto viaPinv = applyBandToCurves(pseudoInverseBand(a, 3), cp, 1);
    CHECK(maxCoordinateDiff(svd, viaPinv) <= 1e-9);
    const Eigen::MatrixXd dense = pseudoInverse(osloMatrix(3, x, y));
    const BandMatrix pinv = pseudoInverseBand(a, 3, 0.0);
    double worst = 0.0;
    for (int i = 0; i < pinv.rows; ++i) {
      for (int s = 0; s < pinv.width(i); ++s) {
        worst = std::max(worst, std::abs(dense(i, pinv.first[static_cast<size_t>(i)] + s) -
                                         pinv.values[pinv.offset[static_cast<size_t>(i)] + static_cast<size_t>(s)]));
      }
    }
    CHECK(worst <= 1e-11);
  }
}

TEST_CASE("The fast reduction makes the specification's decisions", "[reduce]") {
  const BSplineSurface s = syntheticLastSmall();
  struct Case {
    const char* name;
    double threshold;
    KnotChoice choice;
    CurvatureAggregate aggregate;
    ErrorMeasure measure;
    ParamDirection first;
  };
  const Case cases[] = {
      {"curvature max, mean error", 0.2, KnotChoice::Curvature, CurvatureAggregate::Max, ErrorMeasure::Mean, ParamDirection::V},
      {"curvature mean, mean error, u first", 0.5, KnotChoice::Curvature, CurvatureAggregate::Mean, ErrorMeasure::Mean, ParamDirection::U},
      {"fixed curvature order, mean error", 0.2, KnotChoice::CurvatureFixed, CurvatureAggregate::Max, ErrorMeasure::Mean, ParamDirection::V},
      {"fixed curvature order mean, max error, u first", 1.0, KnotChoice::CurvatureFixed, CurvatureAggregate::Mean, ErrorMeasure::Max, ParamDirection::U},
      {"curvature sweeps, mean error", 0.2, KnotChoice::CurvatureSweeps, CurvatureAggregate::Max, ErrorMeasure::Mean, ParamDirection::V},
      {"random, max error", 2.0, KnotChoice::Random, CurvatureAggregate::Max, ErrorMeasure::Max, ParamDirection::V},
      {"everything removable", 1e6, KnotChoice::Curvature, CurvatureAggregate::Max, ErrorMeasure::Mean, ParamDirection::V},
  };
  for (const Case& c : cases) {
    SECTION(c.name) {
      ReductionOptions o;
      o.threshold = c.threshold;
      o.choice = c.choice;
      o.aggregate = c.aggregate;
      o.measure = c.measure;
      o.firstDirection = c.first;
      o.minWindow = 1;  // windows far smaller than the 40- and 56-point curves
      const ReductionResult spec = reduceSurfaceReference(s, o);
      FastPathStats stats;
      const ReductionResult fast = reduceSurface(s, o, nullptr, &stats);
      requireSameReduction(fast, spec, 1e-9);
      WARN(c.name << ": " << stats.windowSolves << " window solves (" << stats.windowRetries
                  << " retries, widest " << stats.widestWindow << "), drift " << stats.drift[0]
                  << " / " << stats.drift[1]);
      CHECK(stats.drift[0] <= 1e-9);
      CHECK(stats.drift[1] <= 1e-9);
      // The explicit A⁺ product (the GPU's route, here in double) gives the same.
      auto cpu = makeReferenceCurveProduct();
      requireSameReduction(reduceSurface(s, o, cpu.get()), spec, 1e-9);
    }
  }
}

TEST_CASE("The fast reduction respects the threshold on a larger surface", "[reduce]") {
  const BSplineSurface s = syntheticLast(150, 180);
  std::map<std::pair<int, double>, long long> kept;  // (choice, threshold) → control points
  for (auto choice : {KnotChoice::Curvature, KnotChoice::CurvatureFixed, KnotChoice::CurvatureSweeps,
                      KnotChoice::Random}) {
    for (double threshold : {0.01, 0.05}) {
      ReductionOptions o;
      o.threshold = threshold;
      o.choice = choice;
      int calls = 0;
      o.progress = [&](const ReductionProgress& p) {
        ++calls;
        CHECK(p.removed <= p.tried);
        CHECK(p.tried <= p.removable);
        if (p.removed < p.tried) CHECK(p.error > 0.0);
      };
      FastPathStats stats;
      const ReductionResult r = reduceSurface(s, o, nullptr, &stats);
      INFO(knotChoiceName(choice) << " at " << threshold);
      kept[{static_cast<int>(choice), threshold}] = r.keptControlPoints;
      // The window solves stay local (they once grew by 2 after every removal until they
      // spanned the whole curve) and agree with the from-scratch fit.
      WARN("150 x 180: widest window " << stats.widestWindow << ", drift " << stats.drift[0]
                                       << " / " << stats.drift[1]);
      CHECK(stats.widestWindow <= 90);
      CHECK(stats.drift[0] <= 1e-9);
      CHECK(stats.drift[1] <= 1e-9);
      validateSurface(r.surface);
      const DeviationStats d = netDeviation(s, r.surface);
      CHECK(d.mean <= threshold);
      CHECK(d.mean == Approx(r.error.mean).margin(1e-12));
      CHECK(d.max == Approx(r.error.max).margin(1e-12));
      int attempts = 0;
      // Every interior knot is tried once per pass: removed or refused (and kept).
      for (const PassReport& pass : r.passes) {
        attempts += pass.removed + pass.refused;
        CHECK(pass.removed + pass.refused == pass.originalCount - 4);
        CHECK(pass.keptCount == pass.originalCount - pass.removed);
        if (pass.refused > 0) CHECK(pass.refusedError > pass.target);
      }
      CHECK(calls == attempts);
      CHECK(r.passes[0].stop == StopReason::Threshold);
      CHECK(r.keptControlPoints < r.originalControlPoints / 4);
    }
  }
  // Re-ranking by bending × span² is what makes the curvature choice compress: the fixed
  // curvature order empties flat stretches first and runs out of error budget early.
  for (double threshold : {0.01, 0.05}) {
    const auto at = [&](KnotChoice c) { return kept[{static_cast<int>(c), threshold}]; };
    WARN("150 x 180 at " << threshold << ": kept " << at(KnotChoice::Curvature) << " (curvature), "
                         << at(KnotChoice::CurvatureFixed) << " (fixed curvature order), "
                         << at(KnotChoice::CurvatureSweeps) << " (sweeps), "
                         << at(KnotChoice::Random) << " (random) of " << 150 * 180);
    CHECK(at(KnotChoice::Curvature) < at(KnotChoice::CurvatureFixed));
  }
}
