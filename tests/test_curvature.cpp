// Principal curvatures, K, H and κ (host/geometry/curvature.h, docs/conventions.md).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "geometry/bezier.h"
#include "geometry/curvature.h"
#include "geometry/rational.h"
#include "geometry/surface_normal.h"

using namespace tessera;

namespace {

// z = (x² + y²)/2 over [−1,1]², x = 2u − 1, y = 2v − 1, as a degree-(2,2) patch:
// x has Bézier coefficients (−1, 0, 1) and x² has (1, −1, 1).
BezierPatch paraboloid() {
  const double X[3] = {-1, 0, 1}, S[3] = {1, -1, 1};
  BezierPatch p{2, 2, {}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) p.cp.emplace_back(X[i], X[j], 0.5 * (S[i] + S[j]));
  return p;
}

// z = xy over [−1,1]²: bilinear.
BezierPatch saddle() {
  return BezierPatch{1, 1, {{-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}, {1, 1, 1}}};
}

// A quarter of the cylinder x² + z² = r², y ∈ [0, 3]: the exact conic arc in u, a line in v.
RationalBezierPatch cylinder(double r) {
  const double w = 1.0 / std::sqrt(2.0);
  const glm::dvec2 arc[3] = {{r, 0}, {r, r}, {0, r}};
  const double weight[3] = {1, w, 1};
  RationalBezierPatch p{2, 1, {}};
  for (int i = 0; i < 3; ++i)
    for (double y : {0.0, 3.0})
      p.cpw.emplace_back(weight[i] * arc[i].x, weight[i] * y, weight[i] * arc[i].y, weight[i]);
  return p;
}

// Monge patch z = f(x, y): K and H from the height function's derivatives (do Carmo §3.3).
void mongeCurvature(double fx, double fy, double fxx, double fxy, double fyy, double& K,
                    double& H) {
  const double g = 1 + fx * fx + fy * fy;
  K = (fxx * fyy - fxy * fxy) / (g * g);
  H = ((1 + fy * fy) * fxx - 2 * fx * fy * fxy + (1 + fx * fx) * fyy) / (2 * std::pow(g, 1.5));
}

// Normal curvature II(T)/I(T) of the tangent T = a·Pu + b·Pv.
double normalCurvature(const SurfaceDerivatives& d, const glm::dvec3& T) {
  const glm::dvec3 n = glm::normalize(glm::cross(d.pu, d.pv));
  const double E = glm::dot(d.pu, d.pu), F = glm::dot(d.pu, d.pv), G = glm::dot(d.pv, d.pv);
  const double tu = glm::dot(T, d.pu), tv = glm::dot(T, d.pv), det = E * G - F * F;
  const double a = (G * tu - F * tv) / det, b = (E * tv - F * tu) / det;
  const double II =
      glm::dot(d.puu, n) * a * a + 2 * glm::dot(d.puv, n) * a * b + glm::dot(d.pvv, n) * b * b;
  return II / glm::dot(a * d.pu + b * d.pv, a * d.pu + b * d.pv);
}

}  // namespace

TEST_CASE("Curvature: paraboloid z = (x^2+y^2)/2 has K = H = kappa = 1 at the origin",
          "[curvature]") {
  const BezierPatch p = paraboloid();
  const double L = controlNetDiagonal(p);
  const SurfaceCurvature c = surfaceCurvature(patchDerivatives(p, 0.5, 0.5), L);
  CHECK_FALSE(c.degenerate);
  CHECK(c.gaussian == Approx(1.0).epsilon(1e-14));
  CHECK(c.mean == Approx(1.0).epsilon(1e-14));
  CHECK(c.k1 == Approx(1.0).epsilon(1e-7));  // √max(H² − K, 0) of a rounding-level difference
  CHECK(c.k2 == Approx(1.0).epsilon(1e-7));
  CHECK(c.kappa == Approx(1.0).epsilon(1e-7));
  CHECK(std::abs(glm::dot(c.dir1, c.dir2)) <= 1e-15);
  CHECK(std::abs(c.dir1.z) <= 1e-15);  // tangent to the plane z = 0 there

  for (double u : {0.0, 0.2, 0.7, 1.0})
    for (double v : {0.1, 0.5, 1.0}) {
      const double x = 2 * u - 1, y = 2 * v - 1;
      double K, H;
      mongeCurvature(x, y, 1, 0, 1, K, H);
      const SurfaceCurvature e = surfaceCurvature(patchDerivatives(p, u, v), L);
      INFO("(x, y) = (" << x << ", " << y << ")");
      CHECK(e.gaussian == Approx(K).epsilon(1e-13));
      CHECK(e.mean == Approx(H).epsilon(1e-13));
      CHECK(e.kappa == Approx(e.k1).epsilon(1e-15));  // both principal curvatures are positive
    }
}

TEST_CASE(
    "Curvature: saddle z = xy has K = -1, H = 0 at the origin, orthogonal principal "
    "directions along the diagonals",
    "[curvature]") {
  const BezierPatch p = saddle();
  const double L = controlNetDiagonal(p);
  const SurfaceCurvature c = surfaceCurvature(patchDerivatives(p, 0.5, 0.5), L);
  CHECK(c.gaussian == Approx(-1.0).epsilon(1e-15));
  CHECK(c.mean == Approx(0.0).margin(1e-15));
  CHECK(c.k1 == Approx(1.0).epsilon(1e-15));
  CHECK(c.k2 == Approx(-1.0).epsilon(1e-15));
  CHECK(c.kappa == Approx(1.0).epsilon(1e-15));
  const double h = std::sqrt(0.5);
  CHECK(std::abs(glm::dot(c.dir1, glm::dvec3(h, h, 0))) == Approx(1.0).epsilon(1e-15));
  CHECK(std::abs(glm::dot(c.dir2, glm::dvec3(h, -h, 0))) == Approx(1.0).epsilon(1e-15));
  CHECK(std::abs(glm::dot(c.dir1, c.dir2)) <= 1e-15);

  for (double u : {0.0, 0.3, 0.9})
    for (double v : {0.2, 1.0}) {
      const double x = 2 * u - 1, y = 2 * v - 1;
      double K, H;
      mongeCurvature(y, x, 0, 1, 0, K, H);
      const SurfaceCurvature e = surfaceCurvature(patchDerivatives(p, u, v), L);
      INFO("(x, y) = (" << x << ", " << y << ")");
      CHECK(e.gaussian == Approx(K).epsilon(1e-14));
      CHECK(e.mean == Approx(H).epsilon(1e-14).margin(1e-15));
    }
}

TEST_CASE(
    "Curvature: cylinder of radius r has K = 0, kappa = 1/r, a straight principal "
    "direction along the axis",
    "[curvature]") {
  const double r = 2.0;
  const RationalBezierPatch p = cylinder(r);
  const double L = controlNetDiagonal(p);
  for (double u : {0.0, 0.3, 0.5, 1.0})
    for (double v : {0.0, 0.6, 1.0}) {
      INFO("(u, v) = (" << u << ", " << v << ")");
      const SurfaceDerivatives d = rationalPatchDerivatives(p, u, v);
      CHECK(glm::length(glm::dvec2(d.p.x, d.p.z)) == Approx(r).epsilon(1e-15));
      const SurfaceCurvature c = surfaceCurvature(d, L);
      CHECK_FALSE(c.degenerate);
      CHECK(c.gaussian == Approx(0.0).margin(1e-14));
      CHECK(std::abs(c.mean) == Approx(0.5 / r).epsilon(1e-13));
      CHECK(c.kappa == Approx(1.0 / r).epsilon(1e-13));
      // The zero curvature belongs to the ruling, the y axis.
      const glm::dvec3 straight = std::abs(c.k1) < std::abs(c.k2) ? c.dir1 : c.dir2;
      CHECK(std::abs(straight.y) == Approx(1.0).epsilon(1e-13));
      CHECK(std::abs(glm::dot(c.dir1, c.dir2)) <= 1e-14);
    }
}

TEST_CASE(
    "Curvature: on random patches the principal directions are orthonormal tangents "
    "whose normal curvatures are k1 and k2 (Euler)",
    "[curvature]") {
  std::mt19937 rng(161803);
  std::uniform_real_distribution<double> coord(-1.0, 1.0), param(0.0, 1.0), angle(0.0, 6.3);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 2 + trial % 4, m = 2 + (trial / 4) % 4;
    BezierPatch p{n, m, {}};
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= m; ++j)
        p.cp.emplace_back(i / double(n), j / double(m), 0.5 * coord(rng));
    const double u = param(rng), v = param(rng);
    const SurfaceDerivatives d = patchDerivatives(p, u, v);
    const SurfaceCurvature c = surfaceCurvature(d, controlNetDiagonal(p));
    const glm::dvec3 normal = unitNormal(d, u, v, controlNetDiagonal(p));
    INFO("trial " << trial << ": degree (" << n << ", " << m << ") at (" << u << ", " << v << ")");
    REQUIRE_FALSE(c.degenerate);
    CHECK(glm::length(c.dir1) == Approx(1.0).epsilon(1e-14));
    CHECK(glm::length(c.dir2) == Approx(1.0).epsilon(1e-14));
    CHECK(std::abs(glm::dot(c.dir1, c.dir2)) <= 1e-14);
    CHECK(std::abs(glm::dot(c.dir1, normal)) <= 1e-14);
    CHECK(std::abs(glm::dot(c.dir2, normal)) <= 1e-14);
    const double scale = 1.0 + c.kappa;
    CHECK(normalCurvature(d, c.dir1) == Approx(c.k1).margin(1e-12 * scale));
    CHECK(normalCurvature(d, c.dir2) == Approx(c.k2).margin(1e-12 * scale));
    CHECK(c.k1 * c.k2 == Approx(c.gaussian).margin(1e-12 * scale * scale));
    CHECK(c.kappa == Approx(std::max(std::abs(c.k1), std::abs(c.k2))).epsilon(1e-15));
    for (int k = 0; k < 5; ++k) {  // k2 ≤ κn(T) ≤ k1 for every tangent T
      const double a = angle(rng);
      const double kn = normalCurvature(d, std::cos(a) * c.dir1 + std::sin(a) * c.dir2);
      CHECK(kn <= c.k1 + 1e-12 * scale);
      CHECK(kn >= c.k2 - 1e-12 * scale);
    }
  }
}

TEST_CASE(
    "Curvature: degenerate points give kappa = 0 and the flag, at the conventions' "
    "threshold |Pu x Pv| <= eps L^2",
    "[curvature]") {
  // The apex row of a cone-like patch: every point of v = 0 is the same.
  BezierPatch apex{2, 2, {}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      apex.cp.emplace_back(j * std::cos(i * 0.5), j * std::sin(i * 0.5), 2.0 - j);
  const SurfaceCurvature c =
      surfaceCurvature(patchDerivatives(apex, 0.4, 0.0), controlNetDiagonal(apex));
  CHECK(c.degenerate);
  CHECK(c.kappa == 0.0);
  CHECK(c.dir1 == glm::dvec3(0.0));
  CHECK_FALSE(
      surfaceCurvature(patchDerivatives(apex, 0.4, 0.01), controlNetDiagonal(apex)).degenerate);

  // EG − F² ≤ (ε·L²)², as docs/conventions.md states (not ε·L⁴): with L = 1, ε = 1e-12,
  // |Pu × Pv| = 1e-11 is regular and 1e-13 is degenerate.
  SurfaceDerivatives d{};
  d.pu = {1, 0, 0};
  d.pv = {0, 1e-11, 0};
  d.puu = {0, 0, 1};
  CHECK_FALSE(surfaceCurvature(d, 1.0).degenerate);
  CHECK(surfaceCurvature(d, 1.0).kappa == Approx(1.0).epsilon(1e-15));
  d.pv = {0, 1e-13, 0};
  CHECK(surfaceCurvature(d, 1.0).degenerate);
  CHECK(surfaceCurvature(d, 1.0).kappa == 0.0);
}
