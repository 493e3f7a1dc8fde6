// Inverse Oslo and the control-point reduction's specification (knot_removal.h): refinement
// is exact, removing a just-inserted knot gives the control points back, the pseudo-inverse is
// the least-squares fit, knot orders, thresholds and limits, and clear errors for bad input.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

#include "reduction/banded_oslo.h"
#include "reduction/knot_removal.h"
#include "bspline/knots.h"
#include "bspline/oslo.h"
#include "reduction/detail/order.h"
#include "experiments/synthetic_surfaces.h"

using namespace tessera;
using Catch::Matchers::Contains;

namespace {

std::vector<glm::dvec3> randomPoints(size_t count, unsigned seed, double scale = 1.0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coord(-scale, scale);
  std::vector<glm::dvec3> pts(count);
  for (auto& q : pts) q = glm::dvec3(coord(rng), coord(rng), coord(rng));
  return pts;
}

double maxDistance(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
  REQUIRE(a.size() == b.size());
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, glm::length(a[i] - b[i]));
  return worst;
}

// Test curves: clamped, unclamped, and one with a double interior knot.
std::vector<BSplineCurve> testCurves() {
  return {
      {3, {0, 0, 0, 0, 0.2, 0.5, 0.5, 0.7, 1, 1, 1, 1}, randomPoints(8, 3)},
      {4, {-1, -0.5, 0, 0.1, 0.4, 0.4, 0.9, 1.3, 1.4, 2, 2.2, 3}, randomPoints(7, 4)},
      {2, openUniformKnots(2, 9), randomPoints(9, 5)},
      {3, openUniformKnots(3, 30, 0.0, 3.0), randomPoints(30, 6, 100.0)},
  };
}

// A surface whose v-curves are circles of radius `radius` (approximately: the control points
// lie on the circle at the Greville abscissae of 64 uniform spans).
BSplineSurface circleRows(double radius) {
  BSplineSurface s;
  s.countU = 5;
  s.countV = 64;
  s.knotsU = openUniformKnots(3, s.countU);
  s.knotsV = openUniformKnots(3, s.countV);
  for (int i = 0; i < s.countU; ++i) {
    for (int j = 0; j < s.countV; ++j) {
      const double a = 2.0 * 3.14159265358979 * j / (s.countV - 1);
      s.cp.push_back({radius * std::cos(a), radius * std::sin(a), 10.0 * i});
    }
  }
  return s;
}

}  // namespace

TEST_CASE("Oslo refinement reproduces the curve exactly", "[reduce]") {
  for (const BSplineCurve& curve : testCurves()) {
    const double lo = curve.knots[static_cast<size_t>(curve.degree)];
    const double hi = curve.knots[curve.cp.size()];
    std::vector<double> inserted;
    for (int k = 1; k < 9; ++k) inserted.push_back(lo + (hi - lo) * k / 9.3);
    inserted.push_back(curve.knots[static_cast<size_t>(curve.degree) + 1]);  // raise a multiplicity
    const BSplineCurve fine = refineCurve(curve, mergeKnots(curve.knots, inserted));
    double worst = 0.0, scale = 1.0;
    for (const auto& q : curve.cp) scale = std::max(scale, glm::length(q));
    for (int k = 0; k <= 500; ++k) {
      const double t = lo + (hi - lo) * k / 500.0;
      worst = std::max(worst, glm::length(curvePoint(fine, t) - curvePoint(curve, t)));
    }
    CHECK(worst <= 1e-14 * scale * 10);
    // The band form holds exactly the dense matrix's entries.
    const Eigen::MatrixXd dense = osloMatrix(curve.degree, curve.knots, fine.knots);
    const BandMatrix band = osloBand(curve.degree, curve.knots, fine.knots);
    Eigen::MatrixXd fromBand = Eigen::MatrixXd::Zero(band.rows, band.cols);
    for (int j = 0; j < band.rows; ++j) {
      for (int s = 0; s < band.width(j); ++s) {
        fromBand(j, band.first[static_cast<size_t>(j)] + s) = band.values[band.offset[static_cast<size_t>(j)] + static_cast<size_t>(s)];
      }
    }
    CHECK((dense - fromBand).cwiseAbs().maxCoeff() == 0.0);
  }
}

TEST_CASE("Removing a knot that was just inserted recovers the control points", "[reduce]") {
  for (const BSplineCurve& curve : testCurves()) {
    const double lo = curve.knots[static_cast<size_t>(curve.degree)];
    const double hi = curve.knots[curve.cp.size()];
    for (double f : {0.13, 0.5, 0.77}) {
      const double t = lo + f * (hi - lo);
      const BSplineCurve inserted = insertKnot(curve, t);  // Boehm: independent of Oslo
      const auto viaSvd = inverseOslo(curve.degree, curve.knots, inserted.knots, inserted.cp);
      const auto viaBand = inverseOsloBanded(curve.degree, curve.knots, inserted.knots, inserted.cp);
      double scale = 1.0;
      for (const auto& q : curve.cp) scale = std::max(scale, glm::length(q));
      CHECK(maxDistance(viaSvd, curve.cp) <= 1e-12 * scale);
      CHECK(maxDistance(viaBand, curve.cp) <= 1e-12 * scale);
    }
    // Many knots inserted at once, all removed at once.
    std::vector<double> many;
    for (int k = 1; k < 20; ++k) many.push_back(lo + (hi - lo) * k / 20.7);
    const BSplineCurve fine = refineCurve(curve, mergeKnots(curve.knots, many));
    CHECK(maxDistance(inverseOslo(curve.degree, curve.knots, fine.knots, fine.cp), curve.cp) <= 1e-11);
  }
}

TEST_CASE("The pseudo-inverse is the least-squares fit", "[reduce]") {
  const BSplineCurve c = testCurves()[3];
  // Coarse knots: the end knots and every third interior knot of the 30-point curve.
  std::vector<double> sub;
  for (size_t k = 0; k < c.knots.size(); ++k) {
    if (k <= 3 || k >= c.cp.size() || k % 3 == 0) sub.push_back(c.knots[k]);
  }
  const Eigen::MatrixXd a = osloMatrix(3, sub, c.knots);
  const Eigen::MatrixXd pinv = pseudoInverse(a);
  CHECK((a * pinv * a - a).cwiseAbs().maxCoeff() < 1e-12);
  CHECK((pinv * a - Eigen::MatrixXd::Identity(a.cols(), a.cols())).cwiseAbs().maxCoeff() < 1e-12);
  // Normal equations: Aᵀ(A·Q − R) = 0 for each coordinate.
  const auto q = inverseOslo(3, sub, c.knots, c.cp);
  const auto refined = applyToControlPoints(a, q);
  for (int axis = 0; axis < 3; ++axis) {
    Eigen::VectorXd residual(a.rows());
    for (Eigen::Index j = 0; j < a.rows(); ++j) residual(j) = refined[static_cast<size_t>(j)][axis] - c.cp[static_cast<size_t>(j)][axis];
    CHECK((a.transpose() * residual).cwiseAbs().maxCoeff() < 1e-10);
  }
}

TEST_CASE("Bad input is rejected with a message naming the reason", "[reduce]") {
  const BSplineCurve c = testCurves()[0];
  std::vector<double> decreasing = c.knots;
  std::swap(decreasing[4], decreasing[5]);
  decreasing[4] = 0.6;
  CHECK_THROWS_WITH(inverseOslo(3, {0, 0, 0, 0, 1, 1, 1, 1}, decreasing, c.cp), Contains("non-decreasing"));
  CHECK_THROWS_WITH(inverseOslo(3, {0, 0, 0, 0, 1, 1, 1, 1}, c.knots, randomPoints(7, 1)), Contains("expected 8"));
  CHECK_THROWS_WITH(inverseOslo(3, {0, 0, 0, 0, 0.3, 1, 1, 1, 1}, c.knots, c.cp), Contains("do not contain"));
  auto withNan = c.cp;
  withNan[2].y = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(inverseOslo(3, {0, 0, 0, 0, 1, 1, 1, 1}, c.knots, withNan), Contains("not finite"));
  CHECK_THROWS_WITH(inverseOsloBanded(3, {0, 0, 0, 0, 1, 1, 1, 1}, c.knots, withNan), Contains("not finite"));
  CHECK_THROWS_WITH(inverseOsloBanded(3, {0, 0, 0, 0, 1, 1, 1, 1}, decreasing, c.cp), Contains("non-decreasing"));

  BSplineSurface s = syntheticLast(8, 9);
  ReductionOptions o;
  for (double bad : {-0.1, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    o.threshold = bad;
    CHECK_THROWS_WITH(reduceSurfaceReference(s, o), Contains("threshold"));
  }
  o.threshold = 0.01;
  o.firstPassShare = 0.0;
  CHECK_THROWS_WITH(reduceSurfaceReference(s, o), Contains("share"));
  o.firstPassShare = 0.5;
  BSplineSurface nan = s;
  nan.at(3, 4).z = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(reduceSurfaceReference(nan, o), Contains("not finite"));
  BSplineSurface shortKnots = s;
  shortKnots.knotsV.pop_back();
  CHECK_THROWS_WITH(reduceSurfaceReference(shortKnots, o), Contains("12 knots is not a B-spline"));
  BSplineSurface badOrder = s;
  std::swap(badOrder.knotsU[5], badOrder.knotsU[6]);
  CHECK_THROWS_WITH(reduceSurfaceReference(badOrder, o), Contains("non-decreasing"));
  BSplineSurface wrongCount = s;
  wrongCount.cp.pop_back();
  CHECK_THROWS_WITH(reduceSurfaceReference(wrongCount, o), Contains("control points for a"));
}

TEST_CASE("Knot curvature and removal orders", "[reduce]") {
  // Circles of radius 50: κ = 1/50 at every interior knot, up to the control polygon's chords.
  const BSplineSurface circles = circleRows(50.0);
  const auto kappa = knotCurvature(circles, ParamDirection::V, CurvatureAggregate::Max);
  for (int k = 4 + 3; k < circles.countV - 3; ++k) CHECK(kappa[static_cast<size_t>(k)] == Approx(0.02).epsilon(0.01));
  // Along u the curves are straight lines.
  for (double k : knotCurvature(circles, ParamDirection::U, CurvatureAggregate::Mean)) CHECK(k == Approx(0.0).margin(1e-12));

  const BSplineSurface s = syntheticLastSmall();
  ReductionOptions o;
  o.choice = KnotChoice::CurvatureFixed;
  for (auto aggregate : {CurvatureAggregate::Max, CurvatureAggregate::Mean}) {
    o.aggregate = aggregate;
    const auto score = knotCurvature(s, ParamDirection::V, aggregate);
    const auto order = removalOrder(s, ParamDirection::V, o);
    REQUIRE(order.size() == static_cast<size_t>(s.countV - 4));
    for (size_t k = 1; k < order.size(); ++k) CHECK(score[static_cast<size_t>(order[k - 1])] <= score[static_cast<size_t>(order[k])]);
  }
  const auto maxScore = knotCurvature(s, ParamDirection::U, CurvatureAggregate::Max);
  const auto meanScore = knotCurvature(s, ParamDirection::U, CurvatureAggregate::Mean);
  for (size_t k = 4; k < static_cast<size_t>(s.countU); ++k) CHECK(maxScore[k] >= meanScore[k]);

  o.choice = KnotChoice::Random;
  o.seed = 7;
  const auto r1 = removalOrder(s, ParamDirection::U, o), r2 = removalOrder(s, ParamDirection::U, o);
  CHECK(r1 == r2);
  CHECK(std::set<int>(r1.begin(), r1.end()).size() == r1.size());
  CHECK(*std::min_element(r1.begin(), r1.end()) == 4);
  CHECK(*std::max_element(r1.begin(), r1.end()) == s.countU - 1);
  o.seed = 8;
  CHECK(removalOrder(s, ParamDirection::U, o) != r1);
}

TEST_CASE("The curvature choice re-ranks by bending over the span a removal would open", "[reduce]") {
  const BSplineSurface circles = circleRows(50.0);
  // Straight curves do not bend.
  for (double b : knotBending(circles, ParamDirection::U, CurvatureAggregate::Max)) CHECK(b == Approx(0.0).margin(1e-12));
  const auto bending = knotBending(circles, ParamDirection::V, CurvatureAggregate::Max);
  const auto kappa = knotCurvature(circles, ParamDirection::V, CurvatureAggregate::Max);
  for (int k = 4; k < circles.countV; ++k) CHECK(bending[static_cast<size_t>(k)] > kappa[static_cast<size_t>(k)]);

  ReductionOptions o;  // KnotChoice::Curvature is the default
  const std::vector<double>& y = circles.knotsV;
  const auto initialScore = [&](int k) {
    const double h = y[static_cast<size_t>(k + 1)] - y[static_cast<size_t>(k - 1)];
    return bending[static_cast<size_t>(k)] * h * h;
  };
  // Every removal refused: the order is the initial scores', each knot once.
  KnotSchedule refused(circles, ParamDirection::V, o);
  REQUIRE(refused.size() == circles.countV - 4);
  std::vector<int> seen;
  for (int k = refused.next(); k >= 0; k = refused.next()) {
    if (!seen.empty()) CHECK(initialScore(seen.back()) <= initialScore(k));
    seen.push_back(k);
    refused.record(k, false);
  }
  CHECK(seen.size() == static_cast<size_t>(refused.size()));
  CHECK(std::set<int>(seen.begin(), seen.end()).size() == seen.size());

  // Every removal accepted on near-constant curvature: a removed knot's neighbours now span
  // 3 knot intervals instead of 2 (score × 2.25), so the removals spread out: no two
  // neighbours among the first third (measured: the first 26 of 60).
  KnotSchedule accepted(circles, ParamDirection::V, o);
  std::set<int> firstThird;
  for (int t = 0; t < accepted.size() / 3; ++t) {
    const int k = accepted.next();
    REQUIRE(k >= 4);
    INFO("removal " << t << ": knot " << k);
    CHECK(firstThird.count(k - 1) == 0);
    CHECK(firstThird.count(k + 1) == 0);
    firstThird.insert(k);
    accepted.record(k, true);
  }
  int rest = 0;
  for (int k = accepted.next(); k >= 0; k = accepted.next(), ++rest) accepted.record(k, true);
  CHECK(static_cast<int>(firstThird.size()) + rest == accepted.size());

  // Sweeps: the fixed order, but within one sweep no removal opens a span around a knot
  // removed in the same sweep; every knot is still tried once.
  o.choice = KnotChoice::CurvatureSweeps;
  const std::vector<int> fixedOrder = removalOrder(circles, ParamDirection::V, o);
  KnotSchedule sweeps(circles, ParamDirection::V, o);
  std::set<int> firstSweep, all;
  bool inFirst = true;
  for (int k = sweeps.next(); k >= 0; k = sweeps.next()) {
    // The first sweep ends where the order wraps around to a deferred knot.
    if (!all.empty() && inFirst && firstSweep.count(k - 1) + firstSweep.count(k + 1) > 0) inFirst = false;
    if (inFirst) firstSweep.insert(k);
    all.insert(k);
    sweeps.record(k, true);
  }
  CHECK(all.size() == fixedOrder.size());
  CHECK(firstSweep.size() >= fixedOrder.size() / 3);
  CHECK(firstSweep.size() <= fixedOrder.size() / 2 + 1);

  // The fixed orders are removalOrder's.
  o.choice = KnotChoice::CurvatureFixed;
  KnotSchedule fixed(circles, ParamDirection::V, o);
  for (int k : removalOrder(circles, ParamDirection::V, o)) CHECK(fixed.next() == k);
  CHECK(fixed.next() == -1);
}

TEST_CASE("The specification respects the threshold and says what stopped it", "[reduce]") {
  const BSplineSurface s = syntheticLastSmall();
  for (auto measure : {ErrorMeasure::Mean, ErrorMeasure::Max}) {
    for (double threshold : {0.2, 1.0}) {
      ReductionOptions o;
      o.threshold = threshold;
      o.measure = measure;
      const ReductionResult r = reduceSurfaceReference(s, o);
      INFO("threshold " << threshold << ", kept " << r.surface.countU << " x " << r.surface.countV);
      validateSurface(r.surface);
      CHECK(r.keptControlPoints < r.originalControlPoints);
      const DeviationStats d = netDeviation(s, r.surface);
      CHECK(d.mean == Approx(r.error.mean).margin(1e-12));
      CHECK(d.max == Approx(r.error.max).margin(1e-12));
      CHECK(d.value(measure) <= threshold);
      CHECK(r.passes[0].error.value(measure) <= 0.5 * threshold);
      for (const PassReport& pass : r.passes) {
        if (pass.stop == StopReason::Threshold) CHECK(pass.refusedError > pass.target);
        CHECK(pass.keptCount == pass.originalCount - pass.removed);
      }
      // The control-net maximum bounds the deviation of the surfaces themselves.
      double sampled = 0.0;
      for (int a = 0; a <= 40; ++a) {
        for (int b = 0; b <= 40; ++b) {
          sampled = std::max(sampled, glm::length(surfacePoint(s, a / 40.0, b / 40.0) - surfacePoint(r.surface, a / 40.0, b / 40.0)));
        }
      }
      CHECK(sampled <= d.max * (1 + 1e-9));
    }
  }
}

TEST_CASE("Any threshold gives a valid surface, down to degree + 1 control points", "[reduce]") {
  const BSplineSurface s = syntheticLast(12, 14);
  ReductionOptions o;
  o.threshold = 1e9;
  const ReductionResult all = reduceSurfaceReference(s, o);
  validateSurface(all.surface);
  CHECK(all.surface.countU == 4);
  CHECK(all.surface.countV == 4);
  CHECK(all.passes[0].stop == StopReason::MinimumControlPoints);
  CHECK(all.passes[1].stop == StopReason::MinimumControlPoints);

  o.threshold = 0.0;
  const ReductionResult none = reduceSurfaceReference(s, o);
  CHECK(none.keptControlPoints == none.originalControlPoints);
  CHECK(none.passes[0].stop == StopReason::Threshold);
  CHECK(none.error.max == 0.0);

  // Already minimal: nothing to remove is not an error.
  BSplineSurface bezier = syntheticLast(4, 4);
  const ReductionResult same = reduceSurfaceReference(bezier, o);
  CHECK(same.passes[0].stop == StopReason::MinimumControlPoints);
  CHECK(same.surface.cp == bezier.cp);
}
