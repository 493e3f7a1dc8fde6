// closestPointOnPatch: the foot point of a point off a patch, the distance never above the
// starting guess's, and the domain boundary respected; the geometric deviation metric built on
// it never exceeds the parametric one.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "geometry/bezier.h"
#include "geometry/closest_point.h"
#include "geometry/rational.h"
#include "mesh/deviation.h"
#include "io/bpt_reader.h"
#include "mesh/tessellate.h"

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

namespace {

BezierPatch bilinearAsBicubic(const glm::dvec3& origin, const glm::dvec3& a, const glm::dvec3& b) {
  BezierPatch p;
  p.cp.resize(16);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) p.at(i, j) = origin + a * (i / 3.0) + b * (j / 3.0);
  return p;
}
}  // namespace

TEST_CASE("distance to a patch: plane and a quarter cylinder", "[deviation]") {
  BezierPatch plane = bilinearAsBicubic({0, 0, 0}, {2, 0, 0}, {0, 3, 0});
  // A point 0.25 above the plane, started from a wrong parameter, lands at the foot.
  CHECK(closestPointOnPatch(plane, {1.2, 0.7, 0.25}, {0.9, 0.1}).distance == Approx(0.25).epsilon(1e-12));
  // Outside the parameter square: the distance to the nearest edge point.
  CHECK(closestPointOnPatch(plane, {3.0, 1.5, 0.0}, {0.5, 0.5}).distance == Approx(1.0).epsilon(1e-9));

  // Quarter circle of radius 1 as a cubic (k = 0.5523), extruded along z: distance of the
  // axis-side point at radius 0.5 is ≈ 0.5 (up to the cubic's 2.7e-4 radial error).
  const double k = 0.5522847498;
  glm::dvec3 ring[4] = {{1, 0, 0}, {1, k, 0}, {k, 1, 0}, {0, 1, 0}};
  BezierPatch cylinder;
  cylinder.cp.resize(16);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) cylinder.at(i, j) = ring[i] + glm::dvec3(0, 0, j / 3.0);
  double s = std::sqrt(0.5) * 0.5;
  CHECK(std::fabs(closestPointOnPatch(cylinder, {s, s, 0.5}, {0.2, 0.2}).distance - 0.5) < 3e-4);
}

TEST_CASE("distance to the surface is at most the parametric deviation", "[deviation]") {
  auto teapot = readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt");
  Backend cpu = makeMirrorBackend();
  QuadtreeOptions o;
  o.linearity = o.flatness = 0.2f;
  Tessellation t = tessellate(teapot, o, cpu);
  DeviationReport parametric = measureDeviation(t, teapot, 3);
  DeviationReport surface = measureDeviation(t, teapot, 3, DeviationMetric::Geometric);
  INFO("teapot at 0.2: " << t.mesh.triangleCount() << " triangles, max distance to surface "
                         << surface.maxDeviation << ", max parametric " << parametric.maxDeviation);
  REQUIRE(surface.samples == parametric.samples);
  for (size_t p = 0; p < teapot.size(); ++p)
    REQUIRE(surface.perPatchMax[p] <= parametric.perPatchMax[p] + 1e-12);
  CHECK(surface.maxDeviation > 0);
  CHECK(surface.meanDeviation < parametric.meanDeviation);
}

TEST_CASE("closest point: a patch in homogeneous form gives the weighted patch's result bit for bit",
          "[deviation]") {
  // A quarter cylinder of radius 1 as a rational biquadratic-by-linear patch (weights 1, √½, 1).
  BezierPatch cylinder;
  cylinder.degreeU = 2, cylinder.degreeV = 1;
  const double w = std::sqrt(0.5);
  const glm::dvec3 arc[3] = {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) {
      cylinder.cp.push_back(arc[i] + glm::dvec3(0, 0, 2.0 * j));
      cylinder.weights.push_back(i == 1 ? w : 1.0);
    }
  const RationalBezierPatch homogeneous = toRationalPatch(cylinder);
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> coord(-1.5, 1.5), param(0.0, 1.0);
  for (int k = 0; k < 50; ++k) {
    const glm::dvec3 target(coord(rng), coord(rng), 1.0 + coord(rng));
    const glm::dvec2 start(param(rng), param(rng));
    const ClosestPoint a = closestPointOnPatch(cylinder, target, start);
    const ClosestPoint b = closestPointOnPatch(homogeneous, target, start);
    CHECK(a.uv == b.uv);
    CHECK(a.point == b.point);
    CHECK(a.distance == b.distance);
    // Off the cylinder's quarter, the distance is at least | |xy| − 1 |.
    CHECK(b.distance >= std::abs(std::hypot(target.x, target.y) - 1.0) - 1e-9);
  }
}

TEST_CASE("closest point: 'enough' ends the search within it and keeps the within-bound answer",
          "[deviation]") {
  // The gap refinement asks only "distance ≤ δ?" and passes δ as `enough`: the answer must be
  // the full search's, on the polynomial and the homogeneous path alike.
  const BezierPatch patch = paraboloid();
  const RationalBezierPatch rational = toRationalPatch(patch);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0), off(-0.3, 0.3);
  int stoppedEarly = 0, over = 0;
  for (int k = 0; k < 400; ++k) {
    const glm::dvec2 uv(unit(rng), unit(rng)), start(unit(rng), unit(rng));
    const glm::dvec3 target = patchPoint(patch, uv.x, uv.y) + glm::dvec3(off(rng), off(rng), off(rng));
    const double bound = 0.02 + 0.2 * unit(rng);
    for (int path = 0; path < 2; ++path) {
      const ClosestPoint full = path == 0 ? closestPointOnPatch(patch, target, start)
                                          : closestPointOnPatch(rational, target, start);
      const ClosestPoint cut = path == 0 ? closestPointOnPatch(patch, target, start, 12, bound)
                                         : closestPointOnPatch(rational, target, start, 12, bound);
      REQUIRE((cut.distance <= bound) == (full.distance <= bound));
      REQUIRE(cut.distance >= full.distance);  // an earlier point of the same descent
      if (full.distance > bound) REQUIRE(cut.distance == full.distance);
      stoppedEarly += cut.distance > full.distance;
      over += full.distance > bound;
      // enough = 0 is the default search.
      const ClosestPoint zero = path == 0 ? closestPointOnPatch(patch, target, start, 12, 0.0)
                                          : closestPointOnPatch(rational, target, start, 12, 0.0);
      REQUIRE(zero.distance == full.distance);
      REQUIRE(zero.uv == full.uv);
    }
  }
  CHECK(stoppedEarly > 0);  // the bound did cut searches short
  CHECK(over > 0);          // and some targets stayed over it
}

TEST_CASE("closest point: the searches' fixed-degree second partials are the checked ones' doubles",
          "[deviation]") {
  // patchSecondDerivativesOfValid and rationalPatchSecondDerivativesOfValid (the degrees fixed at
  // compile time for the CAD import's pairs, at run time otherwise) against the checked
  // evaluators, and closestPointOnValidPatch against closestPointOnPatch.
  std::mt19937 rng(38);
  std::uniform_real_distribution<double> unit(0.0, 1.0), coord(-2.0, 2.0), weight(0.3, 3.0);
  int compared = 0;
  for (int n = 1; n <= 4; ++n)
    for (int m = 1; m <= 4; ++m) {
      BezierPatch patch;
      patch.degreeU = n, patch.degreeV = m;
      for (int k = 0; k < (n + 1) * (m + 1); ++k)
        patch.cp.push_back({coord(rng), coord(rng), coord(rng)});
      BezierPatch weighted = patch;
      for (int k = 0; k < (n + 1) * (m + 1); ++k) weighted.weights.push_back(weight(rng));
      const RationalBezierPatch rational = toRationalPatch(weighted);
      for (int s = 0; s < 20; ++s) {
        const double u = unit(rng), v = unit(rng);
        const SurfaceDerivatives a = patchDerivatives(patch, u, v);
        const SurfaceDerivatives b = patchSecondDerivativesOfValid(patch, u, v);
        REQUIRE((a.p == b.p && a.pu == b.pu && a.pv == b.pv && a.puu == b.puu && a.puv == b.puv &&
                 a.pvv == b.pvv));
        const SurfaceDerivatives c = rationalPatchSecondDerivatives(rational, u, v);
        const SurfaceDerivatives d = rationalPatchSecondDerivativesOfValid(rational, u, v);
        REQUIRE((c.p == d.p && c.pu == d.pu && c.pv == d.pv && c.puu == d.puu && c.puv == d.puv &&
                 c.pvv == d.pvv));
        const glm::dvec3 target = b.p + glm::dvec3(0.1 * coord(rng), 0.1 * coord(rng), 0.1);
        const glm::dvec2 start(unit(rng), unit(rng));
        const ClosestPoint e = closestPointOnPatch(patch, target, start);
        const ClosestPoint f = closestPointOnValidPatch(patch, target, start);
        REQUIRE((e.uv == f.uv && e.point == f.point && e.distance == f.distance));
        const ClosestPoint g = closestPointOnPatch(rational, target, start);
        const ClosestPoint h = closestPointOnValidPatch(rational, target, start);
        REQUIRE((g.uv == h.uv && g.point == h.point && g.distance == h.distance));
        ++compared;
      }
    }
  CHECK(compared == 320);
}
