// View-dependent division counts (host/division/view_dependent.h): TOL in pixels, control points on the
// eye plane and behind it, culling, and the counts driving rule A.
#include <catch2/catch.hpp>

#include <map>
#include <utility>

#include "division/deviation.h"
#include "geometry/homogeneous_net.h"
#include "experiments/rational_samples.h"
#include "division/view_dependent.h"

using namespace tessera;

namespace {

DivisionOptions pixels(double tolerance) {
  DivisionOptions o;
  o.tolerance = tolerance;
  return o;
}

// The measured deviation, in pixels, of the uniform grid of `d` on the patch's screen image.
double screenDeviation(const RationalBezierPatch& world, const Camera& camera, const Divisions& d) {
  return uniformGridDeviation(toNet(screenSpacePatch(world, camera)), d.nu, d.nv);
}

glm::dvec2 toPixels(const Camera& camera, const glm::dvec3& p) {
  const glm::dvec4 c = camera.viewProjection * glm::dvec4(p, 1.0);
  return {0.5 * (c.x / c.w + 1.0) * camera.width, 0.5 * (c.y / c.w + 1.0) * camera.height};
}

}  // namespace

TEST_CASE("View: TOL is in pixels, a patch in front gets counts that meet it on screen",
          "[division][view]") {
  const RationalBezierPatch cyl = quarterCylinder(1.0, 1.0);
  const Camera near = lookAtCamera({3, 3, 0.5}, {0, 0, 0.5}, {0, 0, 1}, 0.8, 1024, 1024);
  const Camera far = lookAtCamera({12, 12, 0.5}, {0, 0, 0.5}, {0, 0, 1}, 0.8, 1024, 1024);
  const ViewDivisions a = viewDivisions(cyl, near, pixels(0.5));
  const ViewDivisions b = viewDivisions(cyl, far, pixels(0.5));
  const ViewDivisions c = viewDivisions(cyl, near, pixels(0.125));
  INFO("near " << a.divisions.nu << "×" << a.divisions.nv << ", far " << b.divisions.nu << "×"
               << b.divisions.nv << ", near at TOL/4 " << c.divisions.nu << "×" << c.divisions.nv);
  CHECK(a.divisions.status == DivisionStatus::Ok);
  CHECK_FALSE(a.eyePlaneFallback);
  CHECK(a.divisions.divisionNumber() > b.divisions.divisionNumber());  // smaller on screen
  CHECK(c.divisions.realU > 1.5 * a.divisions.realU);  // ~√(1/TOL)
  CHECK(screenDeviation(cyl, near, a.divisions) <= 0.5);
  CHECK(screenDeviation(cyl, far, b.divisions) <= 0.5);
  CHECK(screenDeviation(cyl, near, c.divisions) <= 0.125);
}

TEST_CASE("View: eyes on a control point's plane (zero weights) give finite counts within TOL",
          "[division][view]") {
  // A 256² viewport keeps the grids small enough to measure densely (the eye sits at a control
  // point: the near parts of the patches are huge on screen).
  const std::vector<SampleView> views = zeroWeightViews(false, 256, 256);
  REQUIRE(views.size() >= 8);
  for (const SampleView& view : views) {
    INFO(view.name);
    REQUIRE(view.vanishedWeights >= 1);
    DivisionOptions o = pixels(2.0);
    o.maxPerDirection = 4096;
    const ViewDivisions d = viewDivisions(view.patch, view.camera, o);
    INFO("counts " << d.divisions.nu << "×" << d.divisions.nv << " status "
                   << divisionStatusName(d.divisions.status));
    CHECK(d.divisions.status == DivisionStatus::Ok);
    CHECK_FALSE(d.eyePlaneFallback);
    CHECK(d.divisions.nu >= 1);
    CHECK(d.divisions.nv >= 1);
    CHECK(d.divisions.divisionNumber() < 200000);
    CHECK(screenDeviation(view.patch, view.camera, d.divisions) <= 2.0);
  }
}

TEST_CASE("View: control points behind the eye with the patch in front", "[division][view]") {
  // From (0.9, 0.9) the arc's middle control points (1, 1, z) are behind the eye, the arc
  // (cos θ + sin θ ≤ √2 < 1.8) in front.
  const RationalBezierPatch cyl = quarterCylinder(1.0, 1.0);
  const Camera camera = lookAtCamera({0.9, 0.9, 0.5}, {0, 0, 0.5}, {0, 0, 1}, 2.2, 512, 512);
  const RationalBezierPatch screen = screenSpacePatch(cyl, camera);
  CHECK(screen.at(1, 0).w < 0.0);
  CHECK(screen.at(0, 0).w > 0.0);
  DivisionOptions o = pixels(2.0);
  o.maxPerDirection = 4096;
  const ViewDivisions d = viewDivisions(cyl, camera, o);
  INFO("counts " << d.divisions.nu << "×" << d.divisions.nv << ", bounds " << d.divisions.bounds.uu
                 << " " << d.divisions.bounds.uv << " " << d.divisions.bounds.vv);
  CHECK(d.divisions.status == DivisionStatus::Ok);
  CHECK_FALSE(d.eyePlaneFallback);
  CHECK(d.divisions.divisionNumber() < 200000);
  CHECK(screenDeviation(cyl, camera, d.divisions) <= 2.0);
}

TEST_CASE("View: the eye plane cutting the patch falls back to the clipped subdivided bound",
          "[division][view]") {
  // From (0.3, 0.3) inside the cylinder looking along (1, −1): the eye plane passes through
  // the arc's 45° point; the part towards (1, 0) is in front, the part towards (0, 1) behind.
  const RationalBezierPatch cyl = quarterCylinder(1.0, 1.0);
  const Camera camera = lookAtCamera({0.3, 0.3, 0.5}, {1.3, -0.7, 0.5}, {0, 0, 1}, 1.5, 800, 600);
  const RationalBezierPatch screen = screenSpacePatch(cyl, camera);
  CHECK(screen.at(0, 0).w > 0.0);
  CHECK(screen.at(2, 0).w < 0.0);
  DivisionOptions o = pixels(0.5);
  o.maxPerDirection = 2048;
  const ViewDivisions d = viewDivisions(cyl, camera, o);
  INFO("counts " << d.divisions.nu << "×" << d.divisions.nv << " status "
                 << divisionStatusName(d.divisions.status) << ", pieces "
                 << d.divisions.bounds.pieces);
  CHECK(d.eyePlaneFallback);
  CHECK(d.divisions.status != DivisionStatus::Culled);
  CHECK(d.divisions.nu >= 1);
  CHECK(d.divisions.nv >= 1);
  CHECK(d.divisions.nu <= o.maxPerDirection);
  CHECK(d.divisions.nv <= o.maxPerDirection);
}

TEST_CASE("View: a patch entirely behind the eye is culled and meshes to nothing",
          "[division][view]") {
  const RationalBezierPatch cyl = quarterCylinder(1.0, 1.0);
  const Camera away = lookAtCamera({3, 3, 0.5}, {6, 6, 0.5}, {0, 0, 1}, 0.8, 640, 480);
  const ViewDivisions d = viewDivisions(cyl, away, pixels(0.5));
  CHECK(d.divisions.status == DivisionStatus::Culled);
  CHECK(d.divisions.nu == 0);
  CHECK(d.divisions.nv == 0);
  CHECK(uniformGridMesh({cyl}, {d.divisions}).triangleCount() == 0);
}

TEST_CASE("View: counts drive rule A, a torus meshes watertight with per-patch counts",
          "[division][view]") {
  const std::vector<RationalBezierPatch> torus = rationalTorus(2.0, 0.75);
  const Camera camera = lookAtCamera({0, -7, 4}, {0, 0, 0}, {0, 0, 1}, 0.9, 1024, 768);
  std::vector<Divisions> counts;
  long long faces = 0;
  bool differ = false;
  for (const RationalBezierPatch& p : torus) {
    counts.push_back(viewDivisions(p, camera, pixels(0.5)).divisions);
    REQUIRE(counts.back().status == DivisionStatus::Ok);
    faces += counts.back().divisionNumber();
    differ = differ || counts.back().nu != counts.front().nu;
  }
  CHECK(differ);  // near patches need more than far ones
  const TriangleMesh mesh = uniformGridMesh(torus, counts);
  mesh.validate();
  INFO("faces " << faces << ", triangles " << mesh.triangleCount());
  CHECK(mesh.triangleCount() >= size_t(2 * faces));
  // Closed 2-manifold: every undirected edge in exactly two triangles.
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (size_t t = 0; t < mesh.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = mesh.indices[t + k], b = mesh.indices[t + (k + 1) % 3];
      ++edges[{std::min(a, b), std::max(a, b)}];
    }
  int bad = 0;
  for (const auto& e : edges) bad += e.second != 2;
  CHECK(bad == 0);
  // Patch 0's own cells: its vertices lie on its grid and on the surface.
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    if (mesh.patchIds[v] != 0) continue;
    const double u = mesh.uvs[v].x, w = mesh.uvs[v].y;
    const glm::dvec4 h = evaluate(toNet(torus[0]), u, w);
    CHECK(glm::length(glm::dvec3(mesh.positions[v]) - glm::dvec3(h) / h.w) < 1e-5);
  }
  // A single patch: 2·N_u·N_v triangles, and on screen within TOL of its image.
  const TriangleMesh one = uniformGridMesh({torus[0]}, {counts[0]});
  CHECK(one.triangleCount() == size_t(2 * counts[0].divisionNumber()));
  double worst = 0.0;
  const HomogeneousNet net = toNet(torus[0]);
  for (size_t t = 0; t < one.indices.size(); t += 3)
    for (double a : {0.25, 0.5}) {
      const double b = 0.5 * (1.0 - a), c = 1.0 - a - b;
      const uint32_t i0 = one.indices[t], i1 = one.indices[t + 1], i2 = one.indices[t + 2];
      const glm::dvec2 uv = a * glm::dvec2(one.uvs[i0]) + b * glm::dvec2(one.uvs[i1]) +
                            c * glm::dvec2(one.uvs[i2]);
      const glm::dvec4 h = evaluate(net, uv.x, uv.y);
      // The screen triangle's point at the same mix (screen-space affine, as rasterized).
      const glm::dvec2 chord = a * toPixels(camera, one.positions[i0]) +
                               b * toPixels(camera, one.positions[i1]) +
                               c * toPixels(camera, one.positions[i2]);
      worst = std::max(worst, glm::length(toPixels(camera, glm::dvec3(h) / h.w) - chord));
    }
  INFO("worst sampled screen deviation of patch 0's mesh: " << worst << " px");
  CHECK(worst <= 0.5);
}
