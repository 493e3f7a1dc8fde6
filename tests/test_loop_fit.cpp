// The BVH (closest points, intersecting pairs, inside tests against brute force) and Suzuki's
// fitting of Loop control meshes: energy falls, fitted limit points lie on the target, vertices
// that may not move stay bit for bit.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "loop/bvh.h"
#include "loop/fit.h"
#include "loop/limit.h"
#include "loop/shapes.h"

using namespace tessera;

namespace {

TriangleBvh bvhOf(const LoopShape& s) { return TriangleBvh(s.positions, s.topology.triangles); }

LoopShape moved(LoopShape s, const glm::dvec3& offset, double scale) {
  for (auto& p : s.positions) p = scale * p + offset;
  return s;
}

}  // namespace

TEST_CASE("BVH closest points equal brute force over every triangle", "[loop][bvh]") {
  LoopShape s = loopBunny(4, 3);
  TriangleBvh bvh = bvhOf(s);
  uint64_t seed = 7;
  auto next = [&] { seed = seed * 6364136223846793005ull + 1442695040888963407ull; return double(seed >> 11) * 0x1.0p-53 * 4.0 - 2.0; };
  for (int i = 0; i < 300; ++i) {
    const glm::dvec3 p(next(), next(), next());
    double best = 1e300;
    for (uint32_t t = 0; t < bvh.triangleCount(); ++t) {
      glm::dvec3 c[3];
      bvh.corners(t, c);
      const glm::dvec3 q = closestPointOnTriangle(p, c[0], c[1], c[2]);
      best = std::min(best, glm::dot(q - p, q - p));
    }
    REQUIRE(bvh.closest(p).distance2 == best);
  }
}

TEST_CASE("Closest point on a triangle: vertex, edge and face regions", "[loop][bvh]") {
  const glm::dvec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  REQUIRE(closestPointOnTriangle({-1, -1, 3}, a, b, c) == a);
  REQUIRE(closestPointOnTriangle({2, -0.5, 0}, a, b, c) == b);
  REQUIRE(closestPointOnTriangle({0.5, -2, 1}, a, b, c) == glm::dvec3(0.5, 0, 0));
  REQUIRE(glm::length(closestPointOnTriangle({1, 1, 0}, a, b, c) - glm::dvec3(0.5, 0.5, 0)) < 1e-15);
  REQUIRE(glm::length(closestPointOnTriangle({0.2, 0.3, -4}, a, b, c) - glm::dvec3(0.2, 0.3, 0)) < 1e-15);
}

TEST_CASE("BVH intersecting pairs equal brute force; inside tests", "[loop][bvh]") {
  TriangleBvh sphere = bvhOf(loopIcosphere(6));
  TriangleBvh torus = bvhOf(moved(loopTorus(24, 12, 0.02, 4), {0.9, 0.1, 0.05}, 1.0));
  std::vector<std::pair<uint32_t, uint32_t>> fast, slow;
  sphere.forEachIntersecting(torus, [&](uint32_t a, uint32_t b) { fast.push_back({a, b}); });
  forEachIntersectingBruteForce(sphere, torus, [&](uint32_t a, uint32_t b) { slow.push_back({a, b}); });
  std::sort(fast.begin(), fast.end());
  REQUIRE(fast.size() > 20);
  REQUIRE(fast == slow);
  REQUIRE(sphere.inside({0, 0, 0}));
  REQUIRE(sphere.inside({0.5, -0.3, 0.6}));
  REQUIRE_FALSE(sphere.inside({1.2, 0, 0}));
  REQUIRE_FALSE(sphere.inside({0, 3, -1}));
  // The torus's hole is outside it, its tube inside.
  REQUIRE_FALSE(torus.inside({0.9, 0.1, 0.05}));
  REQUIRE(torus.inside({1.9, 0.1, 0.05}));
}

TEST_CASE("Fitting moves a sphere's control mesh until its limit points lie on the sphere",
          "[loop][fit]") {
  // The control vertices start on the unit sphere, so the limit surface shrinks inside it;
  // fitting (λ = 1) must pull every p∞ onto the target.
  LoopShape cage = loopIcosphere(3);
  TriangleBvh target = bvhOf(loopIcosphere(24));
  LoopTopology t = buildLoopTopology(cage.topology);
  std::vector<glm::dvec3> p = cage.positions;
  LoopFitOptions options;
  options.energyThreshold = 1e-12;
  LoopFitReport report = fitLoopToSurface(t, p, target, options);
  WARN("sphere fit: E " << report.energy.front() << " → " << report.energy.back() << " in "
                         << report.iterations << " steps, max |p∞ − q| " << report.maxDistance);
  REQUIRE(report.iterations >= 2);
  for (size_t i = 1; i < report.energy.size(); ++i) REQUIRE(report.energy[i] < report.energy[i - 1]);
  REQUIRE(report.energy.back() < 1e-3 * report.energy.front());
  // On the target polyhedron (measured 1.3e-7), which is within its chordal error (~1e-3 for a
  // 24-frequency icosphere) of the sphere.
  REQUIRE(report.maxDistance < 1e-5);
  auto limit = loopLimitPositions(t, p);
  for (const auto& q : limit) REQUIRE(std::fabs(glm::length(q) - 1.0) < 2e-3);
  REQUIRE(loopFitEnergy(t, p, target, {}) == Approx(report.energy.back()));
}

TEST_CASE("Fitting to a Loop limit surface recovers its control mesh", "[loop][fit]") {
  // The target is the limit surface of the bunny; start from the bunny's cage with noise.
  LoopShape bunny = loopBunny(2, 5);
  LoopTopology t = buildLoopTopology(bunny.topology);
  TriangleBvh target = loopLimitSurfaceBvh(t, bunny.positions, 4);
  std::vector<glm::dvec3> p = bunny.positions;
  for (size_t v = 0; v < p.size(); ++v) p[v] += 0.03 * glm::dvec3(std::sin(3.0 * v), std::cos(5.0 * v), std::sin(7.0 * v));
  double before = 0;
  loopFitEnergy(t, p, target, {}, &before);
  LoopFitReport report = fitLoopToSurface(t, p, target);
  WARN("bunny fit: max |p∞ − q| " << before << " → " << report.maxDistance << ", E "
                                   << report.energy.front() << " → " << report.energy.back()
                                   << " in " << report.iterations << " steps");
  REQUIRE(report.maxDistance < 0.2 * before);
}

TEST_CASE("Fitting moves only the movable vertices, the others bit for bit", "[loop][fit]") {
  LoopShape cage = loopIcosphere(3);
  TriangleBvh target = bvhOf(loopIcosphere(16));
  LoopTopology t = buildLoopTopology(cage.topology);
  std::vector<glm::dvec3> p = cage.positions;
  LoopFitOptions options;
  options.movable.assign(t.vertexCount, 0);
  for (uint32_t v = 0; v < t.vertexCount; ++v) options.movable[v] = cage.positions[v].z > 0.3;
  const double before = loopFitEnergy(t, p, target, options.movable);
  LoopFitReport report = fitLoopToSurface(t, p, target, options);
  REQUIRE(report.energy.back() < 0.1 * before);
  for (uint32_t v = 0; v < t.vertexCount; ++v) {
    if (options.movable[v]) continue;
    REQUIRE(std::memcmp(&p[v], &cage.positions[v], sizeof(glm::dvec3)) == 0);
  }
  options.lambda = 0.0;
  REQUIRE_THROWS_WITH(fitLoopToSurface(t, p, target, options), Catch::Contains("λ = 0"));
}
