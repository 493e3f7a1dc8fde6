// Distance from tessellation samples to the true surface (host/surface_distance.h): exact on
// a plane and a cylinder, never above the parametric deviation, and clearly below it on a
// coarse teapot (the gap between the two metrics that bench_occt reports).
#include <catch2/catch.hpp>

#include <cmath>

#include "deviation.h"
#include "io/bpt_reader.h"
#include "surface_distance.h"
#include "tessellate.h"

using namespace tessera;

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
  CHECK(distanceToPatch(plane, {1.2, 0.7, 0.25}, {0.9, 0.1}) == Approx(0.25).epsilon(1e-12));
  // Outside the parameter square: the distance to the nearest edge point.
  CHECK(distanceToPatch(plane, {3.0, 1.5, 0.0}, {0.5, 0.5}) == Approx(1.0).epsilon(1e-9));

  // Quarter circle of radius 1 as a cubic (k = 0.5523), extruded along z: distance of the
  // axis-side point at radius 0.5 is ≈ 0.5 (up to the cubic's 2.7e-4 radial error).
  const double k = 0.5522847498;
  glm::dvec3 ring[4] = {{1, 0, 0}, {1, k, 0}, {k, 1, 0}, {0, 1, 0}};
  BezierPatch cylinder;
  cylinder.cp.resize(16);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) cylinder.at(i, j) = ring[i] + glm::dvec3(0, 0, j / 3.0);
  double s = std::sqrt(0.5) * 0.5;
  CHECK(std::fabs(distanceToPatch(cylinder, {s, s, 0.5}, {0.2, 0.2}) - 0.5) < 3e-4);
}

TEST_CASE("distance to the surface is at most the parametric deviation", "[deviation]") {
  auto teapot = readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt");
  Backend cpu = makeCpuBackend();
  QuadtreeOptions o;
  o.linearity = o.flatness = 0.2f;
  Tessellation t = tessellate(teapot, o, cpu);
  DeviationReport parametric = measureDeviation(t, teapot, 3);
  DeviationReport surface = measureSurfaceDistance(t, teapot, 3);
  INFO("teapot at 0.2: " << t.mesh.triangleCount() << " triangles, max distance to surface "
                         << surface.maxDeviation << ", max parametric " << parametric.maxDeviation);
  REQUIRE(surface.samples == parametric.samples);
  for (size_t p = 0; p < teapot.size(); ++p)
    REQUIRE(surface.perPatchMax[p] <= parametric.perPatchMax[p] + 1e-12);
  CHECK(surface.maxDeviation > 0);
  CHECK(surface.meanDeviation < parametric.meanDeviation);
}
