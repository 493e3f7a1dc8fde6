// Cox–de Boor basis functions, their derivatives, and B-spline curve/surface evaluation
// (bspline.h), against the recursive definition, finite differences, the Bernstein form and
// the worked numbers of Taniguchi 2000 (papers/004).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "bspline/bspline.h"
#include "bspline/knots.h"

using namespace tessera;

namespace {

struct KnotCase {
  const char* name;
  int degree;
  std::vector<double> knots;
};

// Uniform, open uniform and non-uniform (with a double and a full-multiplicity knot).
std::vector<KnotCase> knotCases() {
  return {
      {"uniform p=3", 3, uniformKnots(3, 7)},
      {"uniform p=2 shifted", 2, uniformKnots(2, 6, -1.0, 0.25)},
      {"open uniform p=2", 2, openUniformKnots(2, 6)},
      {"open uniform p=3 (Bezier)", 3, openUniformKnots(3, 4)},
      {"open uniform p=5", 5, openUniformKnots(5, 9, -2.0, 3.0)},
      {"non-uniform p=3", 3, {0, 0, 0, 0, 0.2, 0.5, 0.5, 0.7, 1, 1, 1, 1}},
      {"non-uniform p=2 break", 2, {0, 0, 0, 0.3, 0.3, 0.3, 0.45, 1, 1, 1}},
      {"non-uniform p=4 unclamped", 4, {-1, -0.5, 0, 0.1, 0.4, 0.4, 0.9, 1.3, 1.4, 2, 2.2, 3}},
      {"degree 7", 7, openUniformKnots(7, 10)},
  };
}

int controlCount(const KnotCase& c) { return static_cast<int>(c.knots.size()) - c.degree - 1; }
double domainLo(const KnotCase& c) { return c.knots[static_cast<size_t>(c.degree)]; }
double domainHi(const KnotCase& c) { return c.knots[static_cast<size_t>(controlCount(c))]; }

// Parameters strictly inside each non-empty domain span, away from knots, where every
// derivative exists and a central difference is meaningful.
std::vector<double> interiorSamples(const KnotCase& c) {
  std::vector<double> ts;
  for (int mu = c.degree; mu < controlCount(c); ++mu) {
    const double a = c.knots[static_cast<size_t>(mu)], b = c.knots[static_cast<size_t>(mu + 1)];
    if (a == b) continue;
    for (double s : {0.13, 0.5, 0.81}) ts.push_back(a + s * (b - a));
  }
  return ts;
}

// The closed domain, ends and every knot included.
std::vector<double> domainSamples(const KnotCase& c, int count = 101) {
  std::vector<double> ts;
  for (int k = 0; k < count; ++k) {
    ts.push_back(domainLo(c) + (domainHi(c) - domainLo(c)) * k / (count - 1));
  }
  for (double x : c.knots) {
    if (x >= domainLo(c) && x <= domainHi(c)) ts.push_back(x);
  }
  return ts;
}

std::vector<glm::dvec3> randomPoints(size_t count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  std::vector<glm::dvec3> pts(count);
  for (auto& q : pts) q = glm::dvec3(coord(rng), coord(rng), coord(rng));
  return pts;
}

double bernstein(int n, int i, double t) {
  double binom = 1.0;
  for (int k = 1; k <= i; ++k) binom = binom * (n - i + k) / k;
  return binom * std::pow(t, i) * std::pow(1.0 - t, n - i);
}

double maxAbs(const glm::dvec3& d) {
  return std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
}

}  // namespace

TEST_CASE("basis: partition of unity and non-negativity", "[bspline]") {
  for (const KnotCase& c : knotCases()) {
    const int n = controlCount(c);
    for (double t : domainSamples(c)) {
      INFO(c.name << ", t = " << t);
      double recursiveSum = 0.0;
      for (int i = 0; i < n; ++i) {
        const double value = basisFunction(i, c.degree, c.knots, t);
        REQUIRE(value >= 0.0);
        recursiveSum += value;
      }
      REQUIRE(recursiveSum == Approx(1.0).margin(1e-14));

      const int span = findSpan(c.degree, c.knots, t);
      const BasisRow row = basisFunctions(span, c.degree, c.knots, t);
      double rowSum = 0.0;
      for (int r = 0; r <= c.degree; ++r) {
        REQUIRE(row[static_cast<size_t>(r)] >= 0.0);
        rowSum += row[static_cast<size_t>(r)];
      }
      REQUIRE(rowSum == Approx(1.0).margin(1e-14));
    }
  }
}

TEST_CASE("basis: the triangular scheme equals the recursive definition", "[bspline]") {
  for (const KnotCase& c : knotCases()) {
    const int n = controlCount(c);
    for (double t : domainSamples(c, 37)) {
      INFO(c.name << ", t = " << t);
      const int span = findSpan(c.degree, c.knots, t);
      const BasisRow row = basisFunctions(span, c.degree, c.knots, t);
      for (int i = 0; i < n; ++i) {
        const int r = i - (span - c.degree);
        const double expected = (r >= 0 && r <= c.degree) ? row[static_cast<size_t>(r)] : 0.0;
        // At a C^-1 break the recursive form reads the right-hand piece, the span search
        // too; everywhere else the two must agree to rounding.
        REQUIRE(basisFunction(i, c.degree, c.knots, t) == Approx(expected).margin(1e-14));
      }
    }
  }
}

TEST_CASE("basis: a knot vector outside its range is rejected", "[bspline]") {
  const std::vector<double> x = openUniformKnots(3, 4);
  REQUIRE_THROWS_AS(basisFunction(4, 3, x, 0.5), std::invalid_argument);
  REQUIRE_THROWS_AS(basisFunction(-1, 3, x, 0.5), std::invalid_argument);
  REQUIRE_THROWS_AS(basisFunctionDerivative(0, 3, x, 0.5, -1), std::invalid_argument);
  // The all-nonzero evaluators need a span of the domain, [p, n-1] = [3, 3] here.
  REQUIRE_THROWS_WITH(basisFunctions(2, 3, x, 0.5), Catch::Matchers::Contains("span 2"));
  REQUIRE_THROWS_AS(basisDerivatives(4, 3, x, 0.5, 2), std::invalid_argument);
  REQUIRE_NOTHROW(basisFunctions(3, 3, x, 0.5));
}

TEST_CASE("basis derivatives: table vs recurrence vs finite differences", "[bspline]") {
  for (const KnotCase& c : knotCases()) {
    const double width = domainHi(c) - domainLo(c);
    const double h = 1e-5 * width;
    for (double t : interiorSamples(c)) {
      INFO(c.name << ", t = " << t);
      const int span = findSpan(c.degree, c.knots, t);
      const BasisTable table =
          basisDerivatives(span, c.degree, c.knots, t, std::min(c.degree + 1, kMaxDegree));
      for (int r = 0; r <= c.degree; ++r) {
        const int i = span - c.degree + r;
        for (int k = 0; k <= c.degree; ++k) {
          INFO("N_" << i << " order " << k);
          double rowScale = 0.0;
          for (double value : table[static_cast<size_t>(k)])
            rowScale = std::max(rowScale, std::abs(value));
          const double exact = basisFunctionDerivative(i, c.degree, c.knots, t, k);
          REQUIRE(table[static_cast<size_t>(k)][static_cast<size_t>(r)] ==
                  Approx(exact).epsilon(1e-12).margin(1e-12 * rowScale));
        }
        if (c.degree < kMaxDegree) {
          REQUIRE(table[static_cast<size_t>(c.degree + 1)][static_cast<size_t>(r)] == 0.0);
        }

        // Central differences of the values and first derivatives: O(h²) error.
        const double n0 = basisFunction(i, c.degree, c.knots, t - h);
        const double n1 = basisFunction(i, c.degree, c.knots, t + h);
        const double fd1 = (n1 - n0) / (2.0 * h);
        REQUIRE(table[1][static_cast<size_t>(r)] == Approx(fd1).margin(1e-6 / width));
        if (c.degree >= 2) {
          const double d0 = basisFunctionDerivative(i, c.degree, c.knots, t - h, 1);
          const double d1 = basisFunctionDerivative(i, c.degree, c.knots, t + h, 1);
          const double fd2 = (d1 - d0) / (2.0 * h);
          REQUIRE(table[2][static_cast<size_t>(r)] ==
                  Approx(fd2).margin(1e-6 / (width * width)).epsilon(1e-6));
        }
      }
    }
  }
}

TEST_CASE("basis: clamped knots with n = p + 1 give the Bernstein polynomials", "[bspline]") {
  for (int p = 1; p <= kMaxDegree; ++p) {
    const std::vector<double> x = openUniformKnots(p, p + 1);
    for (int k = 0; k <= 40; ++k) {
      const double t = k / 40.0;
      const BasisRow row = basisFunctions(findSpan(p, x, t), p, x, t);
      for (int i = 0; i <= p; ++i) {
        INFO("p = " << p << ", i = " << i << ", t = " << t);
        REQUIRE(row[static_cast<size_t>(i)] == Approx(bernstein(p, i, t)).margin(1e-14));
      }
    }
  }
}

TEST_CASE("Taniguchi 2000: knots (0,0,0,0,1,1,1,1) give the cubic Bezier", "[bspline][paper]") {
  const BSplineCurve curve{
      3, {0, 0, 0, 0, 1, 1, 1, 1}, {{1, 1, 0}, {2, 3, 0}, {5, 3, 0}, {4, 1, 0}}};
  REQUIRE_NOTHROW(validateCurve(curve));

  for (int k = 0; k <= 200; ++k) {
    const double t = k / 200.0;
    glm::dvec3 bezier(0.0);
    for (int i = 0; i <= 3; ++i) bezier += bernstein(3, i, t) * curve.cp[static_cast<size_t>(i)];
    INFO("t = " << t);
    REQUIRE(maxAbs(curvePoint(curve, t) - bezier) <= 1e-14);
  }

  // The worked example, §2.2.1: P(0.5) = [3.25 2.5].
  const glm::dvec3 half = curvePoint(curve, 0.5);
  REQUIRE(half.x == Approx(3.25).margin(1e-15));
  REQUIRE(half.y == Approx(2.5).margin(1e-15));
  REQUIRE(half.z == 0.0);
  // Ends interpolate B0 and B3.
  REQUIRE(maxAbs(curvePoint(curve, 0.0) - curve.cp.front()) <= 1e-15);
  REQUIRE(maxAbs(curvePoint(curve, 1.0) - curve.cp.back()) <= 1e-15);

  // Its derivative numbers: P'(0) = [3 6], P'(1) = [-3 -6], P'(1/2) = [4.5 0],
  // P'(1/3) = [5 2], P'(4/5) = [1.08 -3.6], P'(9/10) = [-0.78 -4.8],
  // P'(99/100) = [-2.7618 -5.88]; P''(1/2) = [-6 -12]. The paper prints P''(0) = [6 -12] and
  // P''(1) = [-18 -12], but its own P'' = 6(1-t)B0 - 6(2-3t)B1 + 6(1-3t)B2 + 6tB3 gives
  // [12 -12] and [-24 -12] (= 6(B0 - 2B1 + B2), 6(B1 - 2B2 + B3)): a misprint.
  const struct {
    double t;
    glm::dvec3 d1;
  } firsts[] = {{0.0, {3, 6, 0}},           {1.0, {-3, -6, 0}},     {0.5, {4.5, 0, 0}},
                {1.0 / 3.0, {5, 2, 0}},     {0.8, {1.08, -3.6, 0}}, {0.9, {-0.78, -4.8, 0}},
                {0.99, {-2.7618, -5.88, 0}}};
  for (const auto& f : firsts) {
    INFO("P'(" << f.t << ")");
    REQUIRE(maxAbs(curveDerivatives(curve, f.t).d1 - f.d1) <= 1e-13);
  }
  REQUIRE(maxAbs(curveDerivatives(curve, 0.0).d2 - glm::dvec3(12, -12, 0)) <= 1e-13);
  REQUIRE(maxAbs(curveDerivatives(curve, 0.5).d2 - glm::dvec3(-6, -12, 0)) <= 1e-13);
  REQUIRE(maxAbs(curveDerivatives(curve, 1.0).d2 - glm::dvec3(-24, -12, 0)) <= 1e-13);
}

TEST_CASE("curves: point and derivatives vs the definition and finite differences", "[bspline]") {
  unsigned seed = 1;
  for (const KnotCase& c : knotCases()) {
    const BSplineCurve curve{c.degree, c.knots,
                             randomPoints(static_cast<size_t>(controlCount(c)), seed++)};
    REQUIRE_NOTHROW(validateCurve(curve));
    const double width = domainHi(c) - domainLo(c);
    for (double t : domainSamples(c, 23)) {
      INFO(c.name << ", t = " << t);
      glm::dvec3 byDefinition(0.0);
      for (int i = 0; i < controlCount(c); ++i) {
        byDefinition += basisFunction(i, c.degree, c.knots, t) * curve.cp[static_cast<size_t>(i)];
      }
      REQUIRE(maxAbs(curvePoint(curve, t) - byDefinition) <= 1e-14);
      REQUIRE(maxAbs(curveDerivatives(curve, t).p - byDefinition) <= 1e-14);
    }
    const double h = 1e-5 * width;
    for (double t : interiorSamples(c)) {
      INFO(c.name << ", t = " << t);
      const BSplineCurveDerivatives d = curveDerivatives(curve, t);
      const glm::dvec3 fd1 = (curvePoint(curve, t + h) - curvePoint(curve, t - h)) / (2.0 * h);
      const glm::dvec3 fd2 =
          (curvePoint(curve, t + h) - 2.0 * curvePoint(curve, t) + curvePoint(curve, t - h)) /
          (h * h);
      const double scale1 = 1.0 / width, scale2 = scale1 * scale1;
      REQUIRE(maxAbs(d.d1 - fd1) <= 1e-6 * std::max(1.0, maxAbs(d.d1)) + 1e-7 * scale1);
      REQUIRE(maxAbs(d.d2 - fd2) <= 1e-3 * std::max(1.0, maxAbs(d.d2)) + 1e-3 * scale2);
      if (c.degree == 1) REQUIRE(maxAbs(d.d2) == 0.0);
    }
  }
}

TEST_CASE("curves: clamped ends interpolate the end control points", "[bspline]") {
  const BSplineCurve curve{3, {0, 0, 0, 0, 0.2, 0.5, 0.5, 0.7, 1, 1, 1, 1}, randomPoints(8, 42)};
  REQUIRE(maxAbs(curvePoint(curve, 0.0) - curve.cp.front()) <= 1e-15);
  REQUIRE(maxAbs(curvePoint(curve, 1.0) - curve.cp.back()) <= 1e-15);
  // End tangent p/(x_{n+p-1} − x_{n-1})·(Q_{n-1} − Q_{n-2}), from the span ending at x_n.
  const glm::dvec3 tangent = 3.0 / (1.0 - 0.7) * (curve.cp[7] - curve.cp[6]);
  REQUIRE(maxAbs(curveDerivatives(curve, 1.0).d1 - tangent) <= 1e-13);
}

TEST_CASE("curves: inconsistent sizes throw", "[bspline]") {
  const BSplineCurve tooFewPoints{3, {0, 0, 0, 0, 1, 1, 1, 1}, randomPoints(3, 1)};
  REQUIRE_THROWS_AS(validateCurve(tooFewPoints), std::invalid_argument);
  REQUIRE_THROWS_AS(curvePoint(tooFewPoints, 0.5), std::invalid_argument);
  const BSplineCurve badKnots{2, {0, 0, 0, 1, 0.5, 1, 1}, randomPoints(4, 1)};
  REQUIRE_THROWS_WITH(validateCurve(badKnots), Catch::Matchers::Contains("non-decreasing"));
}

namespace {

BSplineSurface testSurface() {
  BSplineSurface s;
  s.degreeU = 3;
  s.degreeV = 2;
  s.knotsU = {0, 0, 0, 0, 0.3, 0.3, 0.6, 1, 1, 1, 1};  // countU = 7
  s.knotsV = uniformKnots(2, 5, -1.0, 0.5);            // countV = 5, domain [0, 1.5]
  s.countU = 7;
  s.countV = 5;
  s.cp = randomPoints(35, 7);
  return s;
}

}  // namespace

TEST_CASE("surfaces: point equals the double sum of the definition", "[bspline]") {
  const BSplineSurface s = testSurface();
  REQUIRE_NOTHROW(validateSurface(s));
  for (int a = 0; a <= 12; ++a) {
    for (int b = 0; b <= 12; ++b) {
      const double u = a / 12.0, v = 1.5 * b / 12.0;
      glm::dvec3 expected(0.0);
      for (int i = 0; i < s.countU; ++i) {
        for (int j = 0; j < s.countV; ++j) {
          expected += basisFunction(i, s.degreeU, s.knotsU, u) *
                      basisFunction(j, s.degreeV, s.knotsV, v) * s.at(i, j);
        }
      }
      INFO("u = " << u << ", v = " << v);
      REQUIRE(maxAbs(surfacePoint(s, u, v) - expected) <= 1e-14);
      REQUIRE(maxAbs(surfaceDerivatives(s, u, v).p - expected) <= 1e-14);
    }
  }
}

TEST_CASE("surfaces: all partials up to third order vs finite differences", "[bspline]") {
  const BSplineSurface s = testSurface();
  const double h = 1e-4;
  for (double u : {0.1, 0.45, 0.77}) {
    for (double v : {0.2, 0.7, 1.3}) {
      INFO("u = " << u << ", v = " << v);
      const SurfaceDerivatives d = surfaceDerivatives(s, u, v);
      const auto close = [](const glm::dvec3& got, const glm::dvec3& want, double tol) {
        return maxAbs(got - want) <= tol * std::max(1.0, maxAbs(want));
      };
      // Lower-order partials, differenced once, give each next order.
      const SurfaceDerivatives up = surfaceDerivatives(s, u + h, v);
      const SurfaceDerivatives um = surfaceDerivatives(s, u - h, v);
      const SurfaceDerivatives vp = surfaceDerivatives(s, u, v + h);
      const SurfaceDerivatives vm = surfaceDerivatives(s, u, v - h);
      const auto du = [&](glm::dvec3 SurfaceDerivatives::*f) { return (up.*f - um.*f) / (2 * h); };
      const auto dv = [&](glm::dvec3 SurfaceDerivatives::*f) { return (vp.*f - vm.*f) / (2 * h); };
      const double tol = 1e-6;
      REQUIRE(close(d.pu, (surfacePoint(s, u + h, v) - surfacePoint(s, u - h, v)) / (2 * h), tol));
      REQUIRE(close(d.pv, (surfacePoint(s, u, v + h) - surfacePoint(s, u, v - h)) / (2 * h), tol));
      REQUIRE(close(d.puu, du(&SurfaceDerivatives::pu), tol));
      REQUIRE(close(d.puv, du(&SurfaceDerivatives::pv), tol));
      REQUIRE(close(d.puv, dv(&SurfaceDerivatives::pu), tol));
      REQUIRE(close(d.pvv, dv(&SurfaceDerivatives::pv), tol));
      REQUIRE(close(d.puuu, du(&SurfaceDerivatives::puu), tol));
      REQUIRE(close(d.puuv, du(&SurfaceDerivatives::puv), tol));
      REQUIRE(close(d.puvv, du(&SurfaceDerivatives::pvv), tol));
      REQUIRE(close(d.pvvv, glm::dvec3(0.0), 0.0));  // degree 2 in v
      REQUIRE(maxAbs(d.puuu) > 0.0);                 // cubic in u: not trivially zero
    }
  }
}

TEST_CASE("surfaces: one clamped span is the Bezier patch, i along u", "[bspline]") {
  BSplineSurface s;
  s.degreeU = 2;
  s.degreeV = 3;
  s.knotsU = openUniformKnots(2, 3);
  s.knotsV = openUniformKnots(3, 4);
  s.countU = 3;
  s.countV = 4;
  s.cp = randomPoints(12, 99);
  for (double u : {0.0, 0.25, 0.6, 1.0}) {
    for (double v : {0.0, 0.1, 0.5, 0.9, 1.0}) {
      glm::dvec3 expected(0.0);
      for (int i = 0; i <= 2; ++i) {
        for (int j = 0; j <= 3; ++j) {
          expected +=
              bernstein(2, i, u) * bernstein(3, j, v) * s.cp[static_cast<size_t>(i * 4 + j)];
        }
      }
      INFO("u = " << u << ", v = " << v);
      REQUIRE(maxAbs(surfacePoint(s, u, v) - expected) <= 1e-14);
    }
  }
}

TEST_CASE("surfaces: inconsistent nets throw", "[bspline]") {
  BSplineSurface s = testSurface();
  s.cp.pop_back();
  REQUIRE_THROWS_AS(validateSurface(s), std::invalid_argument);
  REQUIRE_THROWS_AS(surfacePoint(s, 0.5, 0.5), std::invalid_argument);
  BSplineSurface t = testSurface();
  t.knotsV[1] = 5.0;
  REQUIRE_THROWS_WITH(validateSurface(t), Catch::Matchers::Contains("knotsV") &&
                                              Catch::Matchers::Contains("non-decreasing"));
}
