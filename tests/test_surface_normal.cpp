// Unit normals, including degenerate points (host/geometry/surface_normal.h, docs/conventions.md).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <utility>

#include "geometry/bezier.h"
#include "geometry/bicubic.h"
#include "geometry/surface_normal.h"

using namespace tessera;

namespace {

// Cubic Bézier quarter circle in the xy-plane, the usual k = 4(√2 − 1)/3 handles.
const double kHandle = 4.0 * (std::sqrt(2.0) - 1.0) / 3.0;
const glm::dvec2 kArc[4] = {{1, 0}, {1, kHandle}, {kHandle, 1}, {0, 1}};
// Bézier coefficients (degree 3) of r(v) = v and of v².
const double kLinear[4] = {0, 1.0 / 3, 2.0 / 3, 1};
const double kSquare[4] = {0, 0, 1.0 / 3, 1};

// A quarter of a dome z = 1 − r² (like the teapot lid's knob top): u runs around the arc,
// v from the apex (r = 0) outwards, so the whole row v = 0 is one point.
BezierPatch dome() {
  BezierPatch p{3, 3, {}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) p.cp.emplace_back(kArc[i] * kLinear[j], 1.0 - kSquare[j]);
  return p;
}

// A quarter of a cone z = 1 − r: the limit normal at the apex differs along each generator.
BezierPatch cone() {
  BezierPatch p{3, 3, {}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) p.cp.emplace_back(kArc[i] * kLinear[j], 1.0 - kLinear[j]);
  return p;
}

// The same surface with the collapsed row moved to edge 0..3: v = 0, v = 1, u = 0, u = 1.
BezierPatch moveCollapsedEdge(const BezierPatch& p, int edge) {
  BezierPatch q = p;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const glm::dvec3 b = p.at(i, j);
      switch (edge) {
        case 0:
          q.at(i, j) = b;
          break;
        case 1:
          q.at(i, 3 - j) = b;
          break;
        case 2:
          q.at(j, i) = b;
          break;
        default:
          q.at(3 - j, i) = b;
          break;
      }
    }
  return q;
}

glm::dvec3 normalAt(const BezierPatch& p, double u, double v) {
  return unitNormal(patchDerivatives(p, u, v), u, v, controlNetDiagonal(p));
}

bool finite(const glm::dvec3& n) {
  return std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z);
}

}  // namespace

TEST_CASE("Unit normal: regular points are normalize(Pu x Pv), L is the box diagonal", "[normal]") {
  BezierPatch plane{1, 2, {{0, 0, 0}, {0, 1, 0}, {0, 2, 0}, {3, 0, 0}, {3, 1, 0}, {3, 2, 0}}};
  CHECK(controlNetDiagonal(plane) == Approx(std::sqrt(13.0)).epsilon(1e-15));
  CHECK(normalAt(plane, 0.3, 0.6) == glm::dvec3(0, 0, 1));
  std::swap(plane.degreeU, plane.degreeV);  // same points read transposed: u and v swap roles
  plane.cp = {{0, 0, 0}, {3, 0, 0}, {0, 1, 0}, {3, 1, 0}, {0, 2, 0}, {3, 2, 0}};
  CHECK(normalAt(plane, 0.3, 0.6) == glm::dvec3(0, 0, -1));

  const BezierPatch d = dome();
  CHECK(controlNetDiagonal(d) == Approx(std::sqrt(3.0)).epsilon(1e-15));
  const SurfaceDerivatives s = patchDerivatives(d, 0.4, 0.7);
  const glm::dvec3 expected = glm::normalize(glm::cross(s.pu, s.pv));
  CHECK(glm::distance(normalAt(d, 0.4, 0.7), expected) <= 1e-15);
}

TEST_CASE("Unit normal: collapsed edge gets the limit of the nearby normals, with their sign",
          "[normal]") {
  const glm::dvec2 inward[4] = {{0, 1}, {0, -1}, {1, 0}, {-1, 0}};
  for (const auto& [name, surface] : {std::pair<const char*, BezierPatch>{"dome", dome()},
                                      std::pair<const char*, BezierPatch>{"cone", cone()}})
    for (int edge = 0; edge < 4; ++edge) {
      const BezierPatch p = moveCollapsedEdge(surface, edge);
      const double L = controlNetDiagonal(p);
      for (int k = 0; k <= 10; ++k) {
        const double s = k / 10.0;
        // The point on the collapsed edge, and points approaching it from inside.
        const glm::dvec2 e = edge == 0   ? glm::dvec2(s, 0)
                             : edge == 1 ? glm::dvec2(s, 1)
                             : edge == 2 ? glm::dvec2(0, s)
                                         : glm::dvec2(1, s);
        INFO(name << ", collapsed edge " << edge << ", s = " << s);
        const SurfaceDerivatives d = patchDerivatives(p, e.x, e.y);
        CHECK(glm::length(glm::cross(d.pu, d.pv)) == 0.0);  // really degenerate, exactly
        const glm::dvec3 n = unitNormal(d, e.x, e.y, L);
        REQUIRE(finite(n));
        CHECK(glm::length(n) == Approx(1.0).epsilon(1e-14));
        // Converges to n from inside (error O(δ)); δ = 1e-7 is still a regular point.
        const glm::dvec2 close = e + 1e-7 * inward[edge];
        const SurfaceDerivatives dc = patchDerivatives(p, close.x, close.y);
        REQUIRE(glm::length(glm::cross(dc.pu, dc.pv)) > 1e-12 * L * L);
        CHECK(glm::distance(n, unitNormal(dc, close.x, close.y, L)) <= 1e-6);
        const glm::dvec2 farther = e + 0.05 * inward[edge];
        CHECK(glm::dot(n, normalAt(p, farther.x, farther.y)) > 0.9);
        // The fast path gives the same normal.
        const glm::dvec3 nb = unitNormal(bicubicDerivatives(p, e.x, e.y), e.x, e.y, L);
        CHECK(glm::distance(n, nb) <= 1e-14);
        if (std::string(name) == "dome") CHECK(std::abs(n.z) == Approx(1.0).epsilon(1e-14));
      }
    }
}

TEST_CASE("Unit normal: second-order limit where Pu and Pv both vanish at a corner", "[normal]") {
  // b_10 = b_01 = b_00: both tangents vanish at (0,0) and so does the first-order term; the
  // normal comes from n'' = 2 A' x B'.
  BezierPatch p{3, 3, {}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) p.cp.emplace_back(i / 3.0, j / 3.0, 0.1 * std::sin(i + 0.5 * j));
  p.at(1, 0) = p.at(0, 1) = p.at(0, 0);
  const double L = controlNetDiagonal(p);
  const SurfaceDerivatives d = patchDerivatives(p, 0.0, 0.0);
  CHECK(d.pu == glm::dvec3(0.0));
  CHECK(d.pv == glm::dvec3(0.0));
  const glm::dvec3 n = unitNormal(d, 0.0, 0.0, L);
  REQUIRE(finite(n));
  CHECK(glm::length(n) == Approx(1.0).epsilon(1e-14));
  CHECK(n.z > 0.9);  // the net is a gently curved sheet over the xy-plane
  // Approaching along d = (1,1)/√2 the normals converge like O(δ).
  for (double delta : {1e-3, 1e-4, 1e-5}) {
    INFO("delta = " << delta);
    CHECK(glm::distance(n, normalAt(p, delta, delta)) <= 10.0 * delta);
  }
}

TEST_CASE("Unit normal: a centre-point degeneracy uses d = (1,1)/sqrt(2)", "[normal]") {
  SurfaceDerivatives d{};
  d.puu = {1, 0, 0};
  d.pvv = {0, 1, 0};  // n'' = 2 du dv (Puu x Pvv): zero if d were (0, 0)
  CHECK(glm::distance(unitNormal(d, 0.5, 0.5, 1.0), glm::dvec3(0, 0, 1)) <= 1e-15);
  CHECK(glm::distance(unitNormal(d, 1.0, 0.0, 1.0), glm::dvec3(0, 0, -1)) <= 1e-15);
}

TEST_CASE("Unit normal: a patch collapsed to a point or a curve has the zero normal, never NaN",
          "[normal]") {
  const BezierPatch point{3, 3, std::vector<glm::dvec3>(16, glm::dvec3(1.1, 2.3, -0.7))};
  const double L = controlNetDiagonal(point);
  CHECK(L == 0.0);
  BezierPatch curve{3, 3, {}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) curve.cp.emplace_back(i, i * i, 0.3);  // every row one point
  for (double u : {0.0, 0.25, 0.5, 1.0})
    for (double v : {0.0, 0.5, 0.75, 1.0}) {
      INFO("(u, v) = (" << u << ", " << v << ")");
      CHECK(normalAt(point, u, v) == glm::dvec3(0.0));
      CHECK(unitNormal(bicubicDerivatives(point, u, v), u, v, L) == glm::dvec3(0.0));
      CHECK(normalAt(curve, u, v) == glm::dvec3(0.0));
    }
}
