// Knot insertion (oslo.h): the Oslo refinement matrix reproduces curves and surfaces, agrees
// with repeated Boehm insertion, and is ready for inverse Oslo by pseudo-inverse.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "bspline/bspline.h"
#include "bspline/knots.h"
#include "bspline/oslo.h"

using namespace tessera;
using Catch::Matchers::Contains;

namespace {

std::vector<glm::dvec3> randomPoints(size_t count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  std::vector<glm::dvec3> pts(count);
  for (auto& q : pts) q = glm::dvec3(coord(rng), coord(rng), coord(rng));
  return pts;
}

double maxAbs(const glm::dvec3& d) {
  return std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
}

double maxDistance(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
  REQUIRE(a.size() == b.size());
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, maxAbs(a[i] - b[i]));
  return worst;
}

double domainLo(const BSplineCurve& c) { return c.knots[static_cast<size_t>(c.degree)]; }
double domainHi(const BSplineCurve& c) { return c.knots[c.cp.size()]; }

// Largest difference between two curves over the first one's domain, knots included.
double curveDistance(const BSplineCurve& a, const BSplineCurve& b) {
  std::vector<double> ts;
  for (int k = 0; k <= 400; ++k)
    ts.push_back(domainLo(a) + (domainHi(a) - domainLo(a)) * k / 400.0);
  for (double x : b.knots) {
    if (x >= domainLo(a) && x <= domainHi(a)) ts.push_back(x);
  }
  double worst = 0.0;
  for (double t : ts) worst = std::max(worst, maxAbs(curvePoint(a, t) - curvePoint(b, t)));
  return worst;
}

BSplineCurve clampedCubic() {
  return {3, {0, 0, 0, 0, 0.2, 0.5, 0.5, 0.7, 1, 1, 1, 1}, randomPoints(8, 3)};
}

BSplineCurve unclampedQuartic() {
  return {4, {-1, -0.5, 0, 0.1, 0.4, 0.4, 0.9, 1.3, 1.4, 2, 2.2, 3}, randomPoints(7, 4)};
}

}  // namespace

TEST_CASE("mergeKnots is a sorted multiset union", "[oslo]") {
  REQUIRE(mergeKnots({0, 0, 1, 1}, {0.5, 0, 0.25}) ==
          std::vector<double>{0, 0, 0, 0.25, 0.5, 1, 1});
}

TEST_CASE("Oslo: no new knots gives the identity", "[oslo]") {
  const BSplineCurve c = clampedCubic();
  const Eigen::MatrixXd a = osloMatrix(3, c.knots, c.knots);
  REQUIRE(a.rows() == 8);
  REQUIRE(a.cols() == 8);
  REQUIRE((a - Eigen::MatrixXd::Identity(8, 8)).cwiseAbs().maxCoeff() <= 1e-15);
}

TEST_CASE("Oslo: refinement reproduces a clamped curve; rows sum to 1", "[oslo]") {
  const BSplineCurve c = clampedCubic();
  // New knots in a span, at an existing simple knot, at the existing double knot (up to
  // p + 1), twice at one new value, and at the domain's first span.
  const std::vector<double> y = mergeKnots(c.knots, {0.05, 0.2, 0.5, 0.6, 0.6, 0.85, 0.9});
  const Eigen::MatrixXd a = osloMatrix(3, c.knots, y);
  REQUIRE(a.rows() == static_cast<Eigen::Index>(c.cp.size() + 7));
  REQUIRE(a.cols() == static_cast<Eigen::Index>(c.cp.size()));
  for (Eigen::Index j = 0; j < a.rows(); ++j) {
    INFO("row " << j);
    REQUIRE(a.row(j).sum() == Approx(1.0).margin(1e-14));
    REQUIRE(a.row(j).minCoeff() >= 0.0);  // discrete B-splines are non-negative
    // Row j mixes at most p + 1 consecutive old points.
    Eigen::Index first = a.cols(), last = -1;
    for (Eigen::Index i = 0; i < a.cols(); ++i) {
      if (a(j, i) != 0.0) {
        first = std::min(first, i);
        last = std::max(last, i);
      }
    }
    REQUIRE(last - first <= 3);
  }
  const BSplineCurve refined = refineCurve(c, y);
  REQUIRE_NOTHROW(validateCurve(refined));
  REQUIRE(curveDistance(c, refined) <= 1e-12);
  // Clamped ends stay interpolated by the same points.
  REQUIRE(maxAbs(refined.cp.front() - c.cp.front()) <= 1e-15);
  REQUIRE(maxAbs(refined.cp.back() - c.cp.back()) <= 1e-15);
}

TEST_CASE("Oslo: refinement reproduces an unclamped curve on its domain", "[oslo]") {
  const BSplineCurve c = unclampedQuartic();  // domain [0.4, 1.3]
  const std::vector<double> y = mergeKnots(c.knots, {0.4, 0.55, 0.7, 0.7, 1.0, 1.3});
  const Eigen::MatrixXd a = osloMatrix(4, c.knots, y);
  for (Eigen::Index j = 0; j < a.rows(); ++j) {
    // Partition of unity holds where y_j lies in the domain [x_p, x_n).
    if (y[static_cast<size_t>(j)] >= 0.4 && y[static_cast<size_t>(j)] < 1.3) {
      INFO("row " << j);
      REQUIRE(a.row(j).sum() == Approx(1.0).margin(1e-14));
    }
  }
  REQUIRE(curveDistance(c, refineCurve(c, y)) <= 1e-12);
}

TEST_CASE("Oslo: inserting many knots at once equals repeated Boehm insertion", "[oslo]") {
  for (const BSplineCurve& c : {clampedCubic(), unclampedQuartic()}) {
    const double lo = domainLo(c), hi = domainHi(c);
    std::vector<double> inserted;
    for (double s : {0.1, 0.33, 0.33, 0.5, 0.9}) inserted.push_back(lo + s * (hi - lo));
    inserted.push_back(c.knots[static_cast<size_t>(c.degree + 1)]);  // an existing knot
    inserted.push_back(hi);                                          // the domain's right end
    if (c.knots.back() == hi) inserted.pop_back();                   // clamped: already at p + 1

    BSplineCurve boehm = c;
    for (double t : inserted) {
      boehm = insertKnot(boehm, t);
      REQUIRE(curveDistance(c, boehm) <= 1e-12);
    }
    const BSplineCurve oslo = refineCurve(c, mergeKnots(c.knots, inserted));
    REQUIRE(oslo.knots == boehm.knots);
    REQUIRE(maxDistance(oslo.cp, boehm.cp) <= 1e-13);
  }
}

TEST_CASE("Boehm: single insertion by hand on the Bezier cubic", "[oslo]") {
  // Inserting 1/2 once into (0,0,0,0,1,1,1,1) moves the inner points to the first
  // de Casteljau level: Q1' = (Q0+Q1)/2, Q2' = (Q1+Q2)/2, Q3' = (Q2+Q3)/2.
  const BSplineCurve c{3, {0, 0, 0, 0, 1, 1, 1, 1}, {{1, 1, 0}, {2, 3, 0}, {5, 3, 0}, {4, 1, 0}}};
  const BSplineCurve r = insertKnot(c, 0.5);
  const std::vector<glm::dvec3> expected{
      {1, 1, 0}, {1.5, 2, 0}, {3.5, 3, 0}, {4.5, 2, 0}, {4, 1, 0}};
  REQUIRE(maxDistance(r.cp, expected) <= 1e-15);
  REQUIRE(r.knots == std::vector<double>{0, 0, 0, 0, 0.5, 1, 1, 1, 1});
}

TEST_CASE("Oslo: bad refinements throw with a reason", "[oslo]") {
  const BSplineCurve c = clampedCubic();
  std::vector<double> missing = mergeKnots(c.knots, {0.3});
  missing.erase(std::find(missing.begin(), missing.end(), 0.2));
  REQUIRE_THROWS_WITH(osloMatrix(3, c.knots, missing), Contains("do not contain every old knot"));
  REQUIRE_THROWS_WITH(osloMatrix(3, c.knots, {0, 0, 0, 1, 1, 1}),
                      Contains("new knots") && Contains("at least 4 control points"));
  REQUIRE_THROWS_WITH(osloMatrix(3, {0, 0, 0, 1, 0.5, 1, 1, 1}, c.knots),
                      Contains("old knots") && Contains("non-decreasing"));
  REQUIRE_THROWS_WITH(osloMatrix(3, c.knots, mergeKnots(c.knots, {1.0})), Contains("multiplicity"));
  std::vector<double> wider = c.knots;
  wider.insert(wider.begin(), -1.0);  // a valid vector, but beyond x_0
  REQUIRE_THROWS_WITH(osloMatrix(3, c.knots, wider), Contains("outside"));
  REQUIRE_THROWS_WITH(insertKnot(c, 1.5), Contains("outside the domain"));
  REQUIRE_THROWS_WITH(insertKnot(c, 0.0), Contains("multiplicity"));
  REQUIRE_THROWS_AS(applyToControlPoints(Eigen::MatrixXd::Identity(3, 3), c.cp),
                    std::invalid_argument);
}

TEST_CASE("Oslo: pseudo-inverse of A recovers the old points (inverse Oslo)", "[oslo]") {
  // A has full column rank, so pinv(A)·A = I and pinv(A)·R = Q exactly for an exact R;
  // Hayashimoto et al. §3.1 use this to remove knots approximately.
  const BSplineCurve c = clampedCubic();
  const std::vector<double> y = mergeKnots(c.knots, {0.1, 0.3, 0.6, 0.8});
  const Eigen::MatrixXd a = osloMatrix(3, c.knots, y);
  const Eigen::MatrixXd pinv = a.completeOrthogonalDecomposition().pseudoInverse();
  const std::vector<glm::dvec3> back = applyToControlPoints(pinv, applyToControlPoints(a, c.cp));
  REQUIRE(maxDistance(back, c.cp) <= 1e-12);
}

namespace {

BSplineSurface testSurface() {
  BSplineSurface s;
  s.degreeU = 3;
  s.degreeV = 2;
  s.knotsU = {0, 0, 0, 0, 0.3, 0.3, 0.6, 1, 1, 1, 1};
  s.knotsV = uniformKnots(2, 5, -1.0, 0.5);  // domain [0, 1.5]
  s.countU = 7;
  s.countV = 5;
  s.cp = randomPoints(35, 11);
  return s;
}

double surfaceDistance(const BSplineSurface& a, const BSplineSurface& b) {
  double worst = 0.0;
  for (int i = 0; i <= 30; ++i) {
    for (int j = 0; j <= 30; ++j) {
      const double u = i / 30.0, v = 1.5 * j / 30.0;
      worst = std::max(worst, maxAbs(surfacePoint(a, u, v) - surfacePoint(b, u, v)));
    }
  }
  return worst;
}

}  // namespace

TEST_CASE("Oslo: surface refinement in u and in v reproduces the surface", "[oslo]") {
  const BSplineSurface s = testSurface();
  const std::vector<double> yU = mergeKnots(s.knotsU, {0.15, 0.45, 0.45, 0.8});
  const std::vector<double> yV = mergeKnots(s.knotsV, {0.25, 0.5, 1.2});

  const BSplineSurface inU = refineSurface(s, ParamDirection::U, yU);
  REQUIRE(inU.countU == 11);
  REQUIRE(inU.countV == 5);
  REQUIRE_NOTHROW(validateSurface(inU));
  REQUIRE(surfaceDistance(s, inU) <= 1e-12);

  const BSplineSurface inV = refineSurface(s, ParamDirection::V, yV);
  REQUIRE(inV.countU == 7);
  REQUIRE(inV.countV == 8);
  REQUIRE(surfaceDistance(s, inV) <= 1e-12);

  const BSplineSurface both = refineSurface(inU, ParamDirection::V, yV);
  REQUIRE(surfaceDistance(s, both) <= 1e-12);
  // The order of the two directions does not matter (the tensor product separates).
  const BSplineSurface other = refineSurface(inV, ParamDirection::U, yU);
  REQUIRE(maxDistance(both.cp, other.cp) <= 1e-14);

  // Each column of the net along u is refined like a curve with the same A.
  for (int j = 0; j < s.countV; ++j) {
    BSplineCurve column{s.degreeU, s.knotsU, {}};
    for (int i = 0; i < s.countU; ++i) column.cp.push_back(s.at(i, j));
    const BSplineCurve refined = refineCurve(column, yU);
    for (int i = 0; i < inU.countU; ++i) {
      REQUIRE(maxAbs(inU.at(i, j) - refined.cp[static_cast<size_t>(i)]) <= 1e-15);
    }
  }
}

TEST_CASE("applyToNet checks the matrix against the net", "[oslo]") {
  const BSplineSurface s = testSurface();
  REQUIRE_THROWS_WITH(applyToNet(Eigen::MatrixXd::Identity(5, 5), s.cp, 7, 5, ParamDirection::U),
                      Contains("does not fit a 7 x 5 net along u"));
  const std::vector<glm::dvec3> same =
      applyToNet(Eigen::MatrixXd::Identity(5, 5), s.cp, 7, 5, ParamDirection::V);
  REQUIRE(maxDistance(same, s.cp) == 0.0);
}
