// Rational Bézier curves and patches (host/geometry/rational.h).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <stdexcept>

#include "geometry/bezier.h"
#include "geometry/rational.h"

using namespace tessera;

namespace {

template <class F>
glm::dvec3 centralDifference(F f, double x, double h = 1e-3) {
  return (-f(x + 2 * h) + 8.0 * f(x + h) - 8.0 * f(x - h) + f(x - 2 * h)) / (12.0 * h);
}

glm::dvec4 homogeneous(const glm::dvec3& p, double w) { return glm::dvec4(w * p, w); }

// The standard conic arc: weights 1, cos 45°, 1 (Farin, §12.5).
RationalBezierCurve quarterCircle() {
  const double w = 1.0 / std::sqrt(2.0);
  return RationalBezierCurve{
      2, {homogeneous({1, 0, 0}, 1), homogeneous({1, 1, 0}, w), homogeneous({0, 1, 0}, 1)}};
}

RationalBezierPatch randomRationalPatch(int n, int m, std::mt19937& rng, double minWeight) {
  std::uniform_real_distribution<double> coord(-1.0, 1.0), weight(minWeight, 2.0);
  RationalBezierPatch p;
  p.degreeU = n;
  p.degreeV = m;
  for (int k = 0; k < (n + 1) * (m + 1); ++k)
    p.cpw.push_back(homogeneous({coord(rng), coord(rng), coord(rng)}, weight(rng)));
  return p;
}

using Field = glm::dvec3 SurfaceDerivatives::*;

}  // namespace

TEST_CASE(
    "Rational curve: quarter circle lies on the unit circle, derivatives match finite "
    "differences",
    "[rational]") {
  const RationalBezierCurve arc = quarterCircle();
  for (int k = 0; k <= 20; ++k) {
    const double t = k / 20.0;
    INFO("t = " << t);
    const glm::dvec3 p = rationalCurvePoint(arc, t);
    CHECK(glm::length(p) == Approx(1.0).epsilon(1e-15));
    CHECK(p.z == 0.0);
    // A circle's tangent is perpendicular to its radius.
    CHECK(glm::dot(p, rationalCurveDerivative(arc, t, 1)) == Approx(0.0).margin(1e-14));
    for (int order = 1; order <= 4; ++order) {
      INFO("order " << order);
      const glm::dvec3 exact = rationalCurveDerivative(arc, t, order);
      const glm::dvec3 fd = centralDifference(
          [&](double s) { return rationalCurveDerivative(arc, s, order - 1); }, t);
      CHECK(glm::distance(exact, fd) <= 1e-7 * (1.0 + glm::length(exact)));
    }
  }
  const double h = std::sqrt(0.5);
  CHECK(glm::distance(rationalCurvePoint(arc, 0.5), glm::dvec3(h, h, 0)) <= 1e-15);
  // P'(0) = 2 w1/w0 (b1 − b0) (Farin §12.3): (0, 2/√2).
  CHECK(glm::distance(rationalCurveDerivative(arc, 0.0, 1), glm::dvec3(0, 2 * h, 0)) <= 1e-14);
}

TEST_CASE("Rational curve: equal weights reproduce the polynomial curve, zero weights",
          "[rational]") {
  const BezierCurve poly{3, {{1, 1, 0}, {2, 3, 0.5}, {5, 3, -1}, {4, 1, 2}}};
  RationalBezierCurve rat{3, {}};
  for (const glm::dvec3& b : poly.cp) rat.cpw.push_back(homogeneous(b, 2.5));
  for (double t : {0.0, 0.3, 0.5, 1.0})
    for (int order = 0; order <= 4; ++order)
      CHECK(glm::distance(rationalCurveDerivative(rat, t, order),
                          curveDerivative(poly, t, order)) <= 1e-12);

  // w0 = 0: the curve starts at infinity; everywhere else it is finite.
  RationalBezierCurve escape{2,
                             {{1, 0, 0, 0}, homogeneous({1, 1, 0}, 1), homogeneous({0, 1, 0}, 1)}};
  CHECK_THROWS_AS(rationalCurvePoint(escape, 0.0), std::domain_error);
  CHECK_THROWS_WITH(rationalCurveDerivative(escape, 0.0, 2), Catch::Contains("denominator"));
  for (double t : {1e-6, 0.1, 0.5, 1.0}) {
    const glm::dvec3 p = rationalCurveDerivative(escape, t, 2);
    CHECK(std::isfinite(p.x + p.y + p.z));
  }
}

TEST_CASE("Rational patch: quotient-rule derivatives vs finite differences", "[rational]") {
  std::mt19937 rng(2718);
  std::uniform_real_distribution<double> param(0.05, 0.95);
  for (int n = 1; n <= kMaxDegree; n += 2)
    for (int m = 1; m <= 4; ++m) {
      RationalBezierPatch p = randomRationalPatch(n, m, rng, 0.2);
      if (n > 1 && m > 1) p.cpw[m + 2] = glm::dvec4(0.3, -0.2, 0.4, 0.0);  // an inner zero weight
      for (int s = 0; s < 4; ++s) {
        const double u = param(rng), v = param(rng);
        const SurfaceDerivatives d = rationalPatchDerivatives(p, u, v);
        CHECK(glm::distance(d.p, rationalPatchPoint(p, u, v)) <= 1e-15 * (1 + glm::length(d.p)));
        auto du = [&](Field f) {
          return centralDifference([&](double x) { return rationalPatchDerivatives(p, x, v).*f; },
                                   u);
        };
        auto dv = [&](Field f) {
          return centralDifference([&](double y) { return rationalPatchDerivatives(p, u, y).*f; },
                                   v);
        };
        const struct {
          const char* name;
          glm::dvec3 exact, fd;
        } checks[] = {
            {"pu", d.pu, du(&SurfaceDerivatives::p)},
            {"pv", d.pv, dv(&SurfaceDerivatives::p)},
            {"puu", d.puu, du(&SurfaceDerivatives::pu)},
            {"puv (u of pv)", d.puv, du(&SurfaceDerivatives::pv)},
            {"puv (v of pu)", d.puv, dv(&SurfaceDerivatives::pu)},
            {"pvv", d.pvv, dv(&SurfaceDerivatives::pv)},
            {"puuu", d.puuu, du(&SurfaceDerivatives::puu)},
            {"puuv", d.puuv, dv(&SurfaceDerivatives::puu)},
            {"puvv", d.puvv, du(&SurfaceDerivatives::pvv)},
            {"pvvv", d.pvvv, dv(&SurfaceDerivatives::pvv)},
        };
        for (const auto& c : checks) {
          INFO("degree (" << n << ", " << m << ") at (" << u << ", " << v << "): " << c.name);
          CHECK(glm::distance(c.exact, c.fd) <= 1e-6 * (1.0 + glm::length(c.exact)));
        }
      }
    }
}

TEST_CASE("Rational patch: second-order partials are the full derivatives' bit for bit",
          "[rational]") {
  std::mt19937 rng(1618);
  std::uniform_real_distribution<double> param(0.0, 1.0);
  for (int n = 1; n <= kMaxDegree; ++n)
    for (int m = 1; m <= kMaxDegree; m += 2) {
      const RationalBezierPatch p = randomRationalPatch(n, m, rng, 0.2);
      for (int s = 0; s < 3; ++s) {
        const double u = param(rng), v = param(rng);
        const SurfaceDerivatives full = rationalPatchDerivatives(p, u, v);
        const SurfaceDerivatives second = rationalPatchSecondDerivatives(p, u, v);
        INFO("degree (" << n << ", " << m << ") at (" << u << ", " << v << ")");
        CHECK(second.p == full.p);
        CHECK(second.pu == full.pu);
        CHECK(second.pv == full.pv);
        CHECK(second.puu == full.puu);
        CHECK(second.puv == full.puv);
        CHECK(second.pvv == full.pvv);
        for (const glm::dvec3& third : {second.puuu, second.puuv, second.puvv, second.pvvv})
          CHECK(third == glm::dvec3(0.0));
      }
    }
}

TEST_CASE("Rational patch: equal weights reproduce the polynomial patch", "[rational]") {
  std::mt19937 rng(55);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  BezierPatch poly{3, 4, {}};
  RationalBezierPatch rat{3, 4, {}};
  for (int k = 0; k < 20; ++k) {
    poly.cp.emplace_back(coord(rng), coord(rng), coord(rng));
    rat.cpw.push_back(homogeneous(poly.cp.back(), 0.7));
  }
  const Field fields[] = {&SurfaceDerivatives::p,    &SurfaceDerivatives::pu,
                          &SurfaceDerivatives::pv,   &SurfaceDerivatives::puu,
                          &SurfaceDerivatives::puv,  &SurfaceDerivatives::pvv,
                          &SurfaceDerivatives::puuu, &SurfaceDerivatives::puuv,
                          &SurfaceDerivatives::puvv, &SurfaceDerivatives::pvvv};
  for (double u : {0.0, 0.4, 1.0})
    for (double v : {0.0, 0.7, 1.0}) {
      const SurfaceDerivatives a = rationalPatchDerivatives(rat, u, v),
                               b = patchDerivatives(poly, u, v);
      for (Field f : fields) CHECK(glm::distance(a.*f, b.*f) <= 1e-12 * (1 + glm::length(b.*f)));
    }
}

TEST_CASE(
    "Rational patch: a zero weight at a corner evaluates finitely where the denominator "
    "is nonzero",
    "[rational]") {
  std::mt19937 rng(8);
  RationalBezierPatch p = randomRationalPatch(3, 3, rng, 0.5);
  p.cpw[0] = glm::dvec4(0.4, 0.1, -0.3, 0.0);  // b_00: weight 0, a direction, not a point
  CHECK_NOTHROW(validateRationalPatch(p));
  for (int a = 0; a <= 10; ++a)
    for (int b = 0; b <= 10; ++b) {
      if (a == 0 && b == 0) continue;
      const double u = a / 10.0, v = b / 10.0;
      INFO("(u, v) = (" << u << ", " << v << ")");
      const SurfaceDerivatives d = rationalPatchDerivatives(p, u, v);
      for (const glm::dvec3& x :
           {d.p, d.pu, d.pv, d.puu, d.puv, d.pvv, d.puuu, d.puuv, d.puvv, d.pvvv})
        CHECK(std::isfinite(x.x + x.y + x.z));
    }
  // Close to the corner the point runs off along b_00's direction, still finite.
  const glm::dvec3 near = rationalPatchPoint(p, 1e-9, 1e-9);
  CHECK(std::isfinite(glm::length(near)));
  CHECK(glm::length(near) > 1e6);
  CHECK_THROWS_AS(rationalPatchPoint(p, 0.0, 0.0), std::domain_error);
  CHECK_THROWS_AS(rationalPatchDerivatives(p, 0.0, 0.0), std::domain_error);
}

TEST_CASE("Rational: invalid input throws invalid_argument", "[rational]") {
  RationalBezierCurve c = quarterCircle();
  c.cpw[1].w = -0.5;
  CHECK_THROWS_WITH(rationalCurvePoint(c, 0.5),
                    Catch::Contains("weight") && Catch::Contains("control point 1"));
  CHECK_THROWS_AS(rationalCurvePoint(c, 0.5), std::invalid_argument);
  CHECK_THROWS_AS(rationalCurveDerivative(quarterCircle(), 0.5, -1), std::invalid_argument);
  CHECK_THROWS_AS(
      validateRationalCurve(RationalBezierCurve{3, std::vector<glm::dvec4>(3, {0, 0, 0, 1})}),
      std::invalid_argument);
  RationalBezierPatch p{2, 8, std::vector<glm::dvec4>(27, {0, 0, 0, 1})};
  CHECK_THROWS_AS(rationalPatchDerivatives(p, 0.5, 0.5), std::invalid_argument);
  p.degreeV = 2;
  p.cpw.resize(9);
  CHECK_NOTHROW(rationalPatchDerivatives(p, 0.5, 0.5));
  p.cpw[4].w = NAN;
  CHECK_THROWS_AS(rationalPatchPoint(p, 0.5, 0.5), std::invalid_argument);
}
