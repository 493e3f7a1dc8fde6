// Bernstein basis, Bézier curves and patches (host/geometry/bernstein.h, host/geometry/bezier.h).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

#include "geometry/bernstein.h"
#include "geometry/bezier.h"

using namespace tessera;

namespace {

BezierPatch randomPatch(int n, int m, std::mt19937& rng) {
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  BezierPatch p;
  p.degreeU = n;
  p.degreeV = m;
  for (int k = 0; k < (n + 1) * (m + 1); ++k) p.cp.emplace_back(coord(rng), coord(rng), coord(rng));
  return p;
}

BezierCurve randomCurve(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  BezierCurve c;
  c.degree = n;
  for (int k = 0; k <= n; ++k) c.cp.emplace_back(coord(rng), coord(rng), coord(rng));
  return c;
}

// Fourth-order central difference: error h⁴/30·f⁽⁵⁾, so h = 1e-3 leaves ~1e-9 even for the
// third derivative of a degree-7 patch, far below the tolerance.
template <class F>
glm::dvec3 centralDifference(F f, double x, double h = 1e-3) {
  return (-f(x + 2 * h) + 8.0 * f(x + h) - 8.0 * f(x - h) + f(x - 2 * h)) / (12.0 * h);
}

// The tensor-product definition summed literally, for checking the index convention.
glm::dvec3 naivePatchPoint(const BezierPatch& p, double u, double v) {
  glm::dvec3 sum(0.0);
  for (int i = 0; i <= p.degreeU; ++i)
    for (int j = 0; j <= p.degreeV; ++j)
      sum += binomial(p.degreeU, i) * std::pow(u, i) * std::pow(1 - u, p.degreeU - i) *
             binomial(p.degreeV, j) * std::pow(v, j) * std::pow(1 - v, p.degreeV - j) * p.at(i, j);
  return sum;
}

// Largest coordinate difference: the paper's points are compared digit by digit.
double maxNorm(const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 e = glm::abs(a - b);
  return std::max(e.x, std::max(e.y, e.z));
}

BezierCurve taniguchiCubic() {
  return BezierCurve{3, {{1, 1, 0}, {2, 3, 0}, {5, 3, 0}, {4, 1, 0}}};
}

}  // namespace

TEST_CASE("Bernstein basis: binomials, partition of unity, Taniguchi Table 1 and eqs. (9), (10)",
          "[bernstein]") {
  CHECK(binomial(7, 3) == 35.0);
  CHECK(binomial(14, 7) == 3432.0);
  CHECK(binomial(3, 4) == 0.0);

  // Table 1 of the control-point-curves paper (n = 3), printed to 3 decimals. Its 0.15 row
  // has J_3,2 = 0.058 where the exact 0.057375 rounds to 0.057 (the 0.85 row prints 0.057 for
  // the same number), hence 7e-4 rather than 5e-4.
  const double table[7][5] = {{0, 1, 0, 0, 0},
                              {0.15, 0.614, 0.325, 0.058, 0.003},
                              {0.35, 0.275, 0.444, 0.239, 0.043},
                              {0.5, 0.125, 0.375, 0.375, 0.125},
                              {0.65, 0.043, 0.239, 0.444, 0.275},
                              {0.85, 0.003, 0.057, 0.325, 0.614},
                              {1, 0, 0, 0, 1}};
  for (const auto& row : table) {
    double b[4];
    bernsteinBasis(3, row[0], b);
    for (int i = 0; i < 4; ++i) {
      INFO("t = " << row[0] << ", i = " << i);
      CHECK(std::abs(b[i] - row[i + 1]) <= 7e-4);
    }
  }

  // Eq. (9) J' = (i − nt)/(t(1−t)) J and eq. (10) J'' = ((i − nt)² − nt² − i(1−2t))/(t²(1−t)²) J,
  // valid for 0 < t < 1; checked against the difference form for every degree.
  for (int n = 0; n <= kMaxDegree; ++n)
    for (double t : {0.1, 0.37, 0.5, 0.83}) {
      double b[8], d1[8], d2[8], d9[8];
      bernsteinBasis(n, t, b);
      bernsteinDerivative(n, 1, t, d1);
      bernsteinDerivative(n, 2, t, d2);
      bernsteinDerivative(n, n + 1, t, d9);
      double sum = 0;
      for (int i = 0; i <= n; ++i) {
        INFO("n = " << n << ", i = " << i << ", t = " << t);
        sum += b[i];
        const double exact = binomial(n, i) * std::pow(t, i) * std::pow(1 - t, n - i);
        CHECK(b[i] == Approx(exact).epsilon(1e-14).margin(1e-15));
        const double e9 = (i - n * t) / (t * (1 - t)) * exact;
        const double e10 = ((i - n * t) * (i - n * t) - n * t * t - i * (1 - 2 * t)) /
                           (t * t * (1 - t) * (1 - t)) * exact;
        CHECK(d1[i] == Approx(e9).epsilon(1e-12).margin(1e-12));
        CHECK(d2[i] == Approx(e10).epsilon(1e-12).margin(1e-12));
        CHECK(d9[i] == 0.0);
      }
      CHECK(sum == Approx(1.0).epsilon(1e-15));
    }
}

TEST_CASE("Bezier curve: control-point-curves paper worked numbers (Taniguchi)", "[bezier]") {
  const BezierCurve c = taniguchiCubic();
  auto P = [&](double t) { return curvePoint(c, t); };
  auto D1 = [&](double t) { return curveDerivative(c, t, 1); };
  auto D2 = [&](double t) { return curveDerivative(c, t, 2); };

  // The paper sums the 3-decimal Table 1, so its P(0.15) and P(0.85) carry up to 2.3e-3 of
  // rounding (P(0.85).x prints 4.198; exactly it is 4.20025; P(0.65).x prints 3.84 for
  // 3.83725): compare each coordinate at that size, then the exact values.
  CHECK(maxNorm(P(0.15), glm::dvec3(1.566, 1.766, 0)) <= 2.5e-3);
  CHECK(maxNorm(P(0.35), glm::dvec3(2.53, 2.367, 0)) <= 2.5e-3);
  CHECK(maxNorm(P(0.65), glm::dvec3(3.84, 2.367, 0)) <= 3e-3);
  CHECK(maxNorm(P(0.85), glm::dvec3(4.198, 1.763, 0)) <= 2.5e-3);
  CHECK(glm::distance(P(0.15), glm::dvec3(1.56475, 1.765, 0)) <= 1e-14);
  CHECK(glm::distance(P(0.85), glm::dvec3(4.20025, 1.765, 0)) <= 1e-14);
  CHECK(glm::distance(P(0.5), glm::dvec3(3.25, 2.5, 0)) <= 1e-15);
  CHECK(P(0.0) == glm::dvec3(1, 1, 0));
  CHECK(P(1.0) == glm::dvec3(4, 1, 0));

  // First derivatives: the printed values are exact.
  CHECK(glm::distance(D1(0.0), glm::dvec3(3, 6, 0)) <= 1e-14);
  CHECK(glm::distance(D1(1.0), glm::dvec3(-3, -6, 0)) <= 1e-14);
  CHECK(glm::distance(D1(0.5), glm::dvec3(4.5, 0, 0)) <= 1e-14);
  CHECK(glm::distance(D1(1.0 / 3.0), glm::dvec3(5, 2, 0)) <= 1e-14);
  CHECK(glm::distance(D1(0.8), glm::dvec3(1.08, -3.6, 0)) <= 1e-14);
  CHECK(glm::distance(D1(0.9), glm::dvec3(-0.78, -4.8, 0)) <= 1e-14);
  CHECK(glm::distance(D1(0.99), glm::dvec3(-2.7618, -5.88, 0)) <= 1e-13);

  // Second derivatives from the paper's own P''(t) = 6(1−t)B0 − 6(2−3t)B1 + 6(1−3t)B2 + 6tB3.
  // It prints P''(0) = [6 −12] and P''(1) = [−18 −12]; both are arithmetic slips: the formula
  // gives 6[1 1] − 12[2 3] + 6[5 3] = [12 −12] and 6[2 3] − 12[5 3] + 6[4 1] = [−24 −12].
  CHECK(glm::distance(D2(0.5), glm::dvec3(-6, -12, 0)) <= 1e-13);
  CHECK(glm::distance(D2(0.0), glm::dvec3(12, -12, 0)) <= 1e-13);
  CHECK(glm::distance(D2(1.0), glm::dvec3(-24, -12, 0)) <= 1e-13);
  CHECK(glm::distance(curveDerivative(c, 0.3, 3), glm::dvec3(-36, 0, 0)) <= 1e-13);
  CHECK(curveDerivative(c, 0.3, 4) == glm::dvec3(0.0));
}

TEST_CASE("Bezier curve: derivatives vs central finite differences, degrees 1..7", "[bezier]") {
  std::mt19937 rng(20261122);
  for (int n = 1; n <= kMaxDegree; ++n) {
    const BezierCurve c = randomCurve(n, rng);
    for (double t : {0.0, 0.21, 0.5, 0.77, 1.0})
      for (int k = 1; k <= n + 1; ++k) {
        INFO("degree " << n << ", order " << k << ", t = " << t);
        const glm::dvec3 exact = curveDerivative(c, t, k);
        const glm::dvec3 fd =
            centralDifference([&](double s) { return curveDerivative(c, s, k - 1); }, t);
        CHECK(glm::distance(exact, fd) <= 1e-7 * (1.0 + glm::length(exact)));
      }
  }
}

TEST_CASE("Bezier patch: evaluation follows the control-point convention", "[bezier]") {
  // Linear precision: b_ij = (i/n, j/m, ·) gives x = u, y = v, so i runs along u.
  BezierPatch p;
  p.degreeU = 4;
  p.degreeV = 2;
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 2; ++j) p.cp.emplace_back(i / 4.0, j / 2.0, std::sin(i + 2.0 * j));
  for (double u : {0.0, 0.3, 1.0})
    for (double v : {0.0, 0.6, 1.0}) {
      const glm::dvec3 q = patchPoint(p, u, v);
      CHECK(q.x == Approx(u).margin(1e-15));
      CHECK(q.y == Approx(v).margin(1e-15));
    }

  std::mt19937 rng(7);
  for (int n = 1; n <= kMaxDegree; ++n)
    for (int m = 1; m <= kMaxDegree; ++m) {
      const BezierPatch r = randomPatch(n, m, rng);
      for (double u : {0.0, 0.4, 1.0})
        for (double v : {0.0, 0.15, 1.0}) {
          INFO("degree (" << n << ", " << m << ") at (" << u << ", " << v << ")");
          CHECK(glm::distance(patchPoint(r, u, v), naivePatchPoint(r, u, v)) <= 1e-14);
          CHECK(patchDerivatives(r, u, v).p == patchPoint(r, u, v));
        }
    }
}

TEST_CASE("Bezier patch: derivatives vs central finite differences, degrees 1..7", "[bezier]") {
  std::mt19937 rng(1234567);
  std::uniform_real_distribution<double> param(0.0, 1.0);
  for (int n = 1; n <= kMaxDegree; ++n)
    for (int m = 1; m <= kMaxDegree; ++m) {
      const BezierPatch p = randomPatch(n, m, rng);
      for (int s = 0; s < 4; ++s) {
        const double u = s == 0 ? 0.0 : param(rng), v = s == 0 ? 1.0 : param(rng);
        const SurfaceDerivatives d = patchDerivatives(p, u, v);
        auto at = [&](double uu, double vv) { return patchDerivatives(p, uu, vv); };
        using Field = glm::dvec3 SurfaceDerivatives::*;
        auto du = [&](Field f) {
          return centralDifference([&](double x) { return at(x, v).*f; }, u);
        };
        auto dv = [&](Field f) {
          return centralDifference([&](double y) { return at(u, y).*f; }, v);
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
            {"puuv (v of puu)", d.puuv, dv(&SurfaceDerivatives::puu)},
            {"puuv (u of puv)", d.puuv, du(&SurfaceDerivatives::puv)},
            {"puvv", d.puvv, du(&SurfaceDerivatives::pvv)},
            {"pvvv", d.pvvv, dv(&SurfaceDerivatives::pvv)},
        };
        for (const auto& c : checks) {
          INFO("degree (" << n << ", " << m << ") at (" << u << ", " << v << "): " << c.name);
          CHECK(glm::distance(c.exact, c.fd) <= 1e-7 * (1.0 + glm::length(c.exact)));
        }
      }
    }
}

TEST_CASE("Bezier curve: de Casteljau subdivision and sub-curves reproduce the curve", "[bezier]") {
  std::mt19937 rng(99);
  for (int n = 1; n <= kMaxDegree; ++n) {
    const BezierCurve c = randomCurve(n, rng);
    for (double t : {0.25, 0.5, 0.9}) {
      const auto halves = subdivideCurve(c, t);
      CHECK(halves.first.cp.front() == c.cp.front());
      CHECK(halves.second.cp.back() == c.cp.back());
      CHECK(halves.first.cp.back() == halves.second.cp.front());
      for (double s = 0; s <= 1.0; s += 0.125) {
        INFO("degree " << n << ", split at " << t << ", s = " << s);
        CHECK(glm::distance(curvePoint(halves.first, s), curvePoint(c, s * t)) <= 1e-14);
        CHECK(glm::distance(curvePoint(halves.second, s), curvePoint(c, t + s * (1 - t))) <= 1e-14);
      }
    }
    const BezierCurve piece = subCurve(c, 0.8, 0.3);  // reversed
    for (double s = 0; s <= 1.0; s += 0.125)
      CHECK(glm::distance(curvePoint(piece, s), curvePoint(c, 0.8 - 0.5 * s)) <= 1e-14);
  }
}

TEST_CASE("Bezier patch: de Casteljau subdivision and sub-patches reproduce the surface",
          "[bezier]") {
  std::mt19937 rng(4242);
  for (int n = 1; n <= kMaxDegree; ++n)
    for (int m = 1; m <= kMaxDegree; m += 2) {
      const BezierPatch p = randomPatch(n, m, rng);
      const double t = 0.37;
      const auto us = subdividePatchU(p, t);
      const auto vs = subdividePatchV(p, t);
      const BezierPatch sub = subPatch(p, 0.2, 0.7, 0.55, 0.95);
      const BezierPatch left = subPatch(p, 0.0, t, 0.0, 1.0);
      double worst = 0;
      for (double a = 0; a <= 1.0; a += 0.1)
        for (double b = 0; b <= 1.0; b += 0.1) {
          worst =
              std::max(worst, glm::distance(patchPoint(us.first, a, b), patchPoint(p, a * t, b)));
          worst = std::max(
              worst, glm::distance(patchPoint(us.second, a, b), patchPoint(p, t + a * (1 - t), b)));
          worst =
              std::max(worst, glm::distance(patchPoint(vs.first, a, b), patchPoint(p, a, b * t)));
          worst = std::max(
              worst, glm::distance(patchPoint(vs.second, a, b), patchPoint(p, a, t + b * (1 - t))));
          worst = std::max(worst, glm::distance(patchPoint(sub, a, b),
                                                patchPoint(p, 0.2 + 0.5 * a, 0.55 + 0.4 * b)));
        }
      INFO("degree (" << n << ", " << m << ")");
      CHECK(worst <= 1e-12);
      for (size_t k = 0; k < p.cp.size(); ++k)
        CHECK(glm::distance(left.cp[k], us.first.cp[k]) <= 1e-14);
      // The split shares the boundary curve exactly.
      for (int j = 0; j <= m; ++j) CHECK(us.first.at(n, j) == us.second.at(0, j));
    }
}

TEST_CASE("Bezier: invalid degrees, counts and parameters throw invalid_argument", "[bezier]") {
  CHECK_THROWS_AS(curvePoint(BezierCurve{0, {{0, 0, 0}}}, 0.5), std::invalid_argument);
  CHECK_THROWS_AS(curvePoint(BezierCurve{8, std::vector<glm::dvec3>(9)}, 0.5),
                  std::invalid_argument);
  CHECK_THROWS_AS(curveDerivative(BezierCurve{3, std::vector<glm::dvec3>(3)}, 0.5, 1),
                  std::invalid_argument);
  CHECK_THROWS_AS(curveDerivative(taniguchiCubic(), 0.5, -1), std::invalid_argument);
  CHECK_THROWS_AS(subdivideCurve(taniguchiCubic(), NAN), std::invalid_argument);
  CHECK_THROWS_WITH(curvePoint(BezierCurve{3, std::vector<glm::dvec3>(5)}, 0.5),
                    Catch::Contains("needs 4 control points, got 5"));

  BezierPatch p{3, 3, std::vector<glm::dvec3>(15)};
  CHECK_THROWS_AS(patchDerivatives(p, 0.5, 0.5), std::invalid_argument);
  p.cp.resize(16);
  CHECK_NOTHROW(patchDerivatives(p, 0.5, 0.5));
  p.degreeV = 8;
  CHECK_THROWS_WITH(patchPoint(p, 0.5, 0.5), Catch::Contains("outside 1..7"));
  p.degreeV = 3;
  CHECK_THROWS_AS(subPatch(p, 0, INFINITY, 0, 1), std::invalid_argument);
  CHECK_THROWS_AS(validatePatch(BezierPatch{2, 3, std::vector<glm::dvec3>(16)}),
                  std::invalid_argument);
  CHECK_THROWS_AS(bernsteinDerivative(8, 1, 0.5, nullptr), std::invalid_argument);
}

TEST_CASE("Bernstein: every partial at once equals each partial alone, bit for bit",
          "[bezier]") {
  // tensorPartials shares one table of u-differences between the partials; the values must be
  // tensorPartial's exactly (the derivative evaluators moved to it, and the meshes keep their bytes).
  std::mt19937 rng(20261127);
  std::uniform_real_distribution<double> coord(-3.0, 3.0), param(0.0, 1.0);
  size_t compared = 0;
  for (int n = 1; n <= kMaxDegree; ++n)
    for (int m = 1; m <= kMaxDegree; ++m) {
      std::vector<glm::dvec4> net((n + 1) * (m + 1));
      for (glm::dvec4& p : net) p = {coord(rng), coord(rng), coord(rng), 0.5 + 0.25 * coord(rng)};
      net[1] = net[0];  // a collapsed edge start: exact zeros must stay exact
      const BernsteinTriangle bu = bernsteinTriangle(n, param(rng));
      const BernsteinTriangle bv = bernsteinTriangle(m, param(rng));
      glm::dvec4 all[4][4];
      tensorPartials<glm::dvec4, 3>(net.data(), n, m, bu, bv, all);
      for (int a = 0; a <= 3; ++a)
        for (int b = 0; a + b <= 3; ++b) {
          const glm::dvec4 alone = tensorPartial(net.data(), n, m, a, b, bu, bv);
          INFO("degree " << n << "x" << m << ", partial " << a << "," << b);
          REQUIRE(std::memcmp(&alone, &all[a][b], sizeof alone) == 0);
          ++compared;
        }
    }
  CHECK(compared == 49 * 10);
}
