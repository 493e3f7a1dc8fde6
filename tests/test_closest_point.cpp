// closestPointOnPatch: the foot point of a point off a patch, the distance never above the
// starting guess's, and the domain boundary respected.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "bezier.h"
#include "closest_point.h"

using namespace tessera;

namespace {

// z = (x² + y²)/4 over [0,2]² as a biquadratic-in-disguise bicubic (exact: x, y linear in u, v).
BezierPatch paraboloid() {
  BezierPatch p;
  p.cp.resize(16);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double x = 2.0 * i / 3.0, y = 2.0 * j / 3.0;
      // Bernstein coefficients of u² (resp. v²) in degree 3: 0, 0, 1/3, 1.
      const double cu[4] = {0, 0, 1.0 / 3.0, 1}, cv[4] = {0, 0, 1.0 / 3.0, 1};
      p.at(i, j) = glm::dvec3(x, y, cu[i] + cv[j]);  // z = u² + v² = (x² + y²)/4
    }
  return p;
}

}  // namespace

TEST_CASE("closest point: a point above a plane drops straight down", "[deviation]") {
  BezierPatch plane;
  plane.cp.resize(16);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) plane.at(i, j) = glm::dvec3(i, j, 0);  // x = 3u, y = 3v
  const ClosestPoint c = closestPointOnPatch(plane, {1.2, 2.1, 0.5}, {0.9, 0.1});
  CHECK(c.distance == Approx(0.5).margin(1e-12));
  CHECK(c.uv.x == Approx(0.4).margin(1e-9));
  CHECK(c.uv.y == Approx(0.7).margin(1e-9));
}

TEST_CASE("closest point: random points near a paraboloid find the foot point", "[deviation]") {
  const BezierPatch p = paraboloid();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.1, 0.9), offset(-0.05, 0.05);
  double worstResidual = 0;
  for (int k = 0; k < 200; ++k) {
    const glm::dvec2 uv(unit(rng), unit(rng));
    const SurfaceDerivatives d = patchDerivatives(p, uv.x, uv.y);
    const glm::dvec3 n = glm::normalize(glm::cross(d.pu, d.pv));
    const double h = offset(rng);
    const glm::dvec3 target = d.p + h * n;  // the foot point of target is d.p
    const glm::dvec2 start = uv + glm::dvec2(offset(rng), offset(rng));
    const ClosestPoint c = closestPointOnPatch(p, target, start);
    REQUIRE(c.distance <= glm::distance(patchPoint(p, start.x, start.y), target) + 1e-15);
    worstResidual = std::max(worstResidual, std::fabs(c.distance - std::fabs(h)));
  }
  INFO("largest |distance − true offset|: " << worstResidual);
  CHECK(worstResidual < 1e-9);
}

TEST_CASE("closest point: the search stays in the domain", "[deviation]") {
  const BezierPatch p = paraboloid();
  // Beyond the corner (u, v) = (1, 1): the foot point is the corner itself.
  const ClosestPoint c = closestPointOnPatch(p, {3, 3, 2}, {0.5, 0.5});
  CHECK(c.uv.x == 1.0);
  CHECK(c.uv.y == 1.0);
  CHECK(c.distance == Approx(glm::distance(glm::dvec3(3, 3, 2), glm::dvec3(2, 2, 2))));
}
