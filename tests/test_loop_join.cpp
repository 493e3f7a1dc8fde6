// Joining two Loop control meshes by local refinement (host/loop/join.h): the result is a
// closed, consistently oriented 2-manifold of the expected genus, vertices away from the seam
// are bit for bit the input's, and the fitted vertices' limit points lie near the original
// surfaces. Sphere + torus, sphere + a bumpy (bunny-like) shape, and "paste" of a cut part.
#include <catch2/catch.hpp>

#include <cstring>
#include <string>
#include <utility>

#include "loop/join.h"
#include "loop/limit.h"

using namespace tessera;

namespace {

LoopShape placed(LoopShape s, const glm::dvec3& offset, double scale) {
  for (auto& p : s.positions) p = scale * p + offset;
  return s;
}

// Closed, oriented (buildLoopTopology checks each edge has two faces in opposite directions),
// positive volume, Euler characteristic; every unfitted input vertex exactly the input's.
void requireGoodJoin(const LoopJoinResult& r, const LoopShape& a, const LoopShape& b, int euler) {
  const LoopTopology t = buildLoopTopology(r.mesh.topology);
  REQUIRE(t.closed());
  REQUIRE(long(t.vertexCount) - long(t.edgeCount()) + long(t.faceCount()) == euler);
  REQUIRE(signedVolume(r.mesh) > 0);
  size_t unchanged = 0;
  for (uint32_t v = 0; v < t.vertexCount; ++v) {
    if (r.fitted[v]) continue;
    REQUIRE(r.source[v] != kLoopNone);
    const glm::dvec3& original = (r.side[v] == 0 ? a : b).positions[r.source[v]];
    REQUIRE(std::memcmp(&r.mesh.positions[v], &original, sizeof(glm::dvec3)) == 0);
    ++unchanged;
  }
  REQUIRE(unchanged == r.report.unchangedVertices);
  const auto& rep = r.report;
  WARN(r.mesh.name << ": levels " << rep.levelsA << "/" << rep.levelsB << ", interfering "
                   << rep.interferingA << "/" << rep.interferingB << " triangles, triangles "
                   << rep.trianglesIn << " → " << rep.trianglesOut << " (bridge "
                   << rep.bridgeTriangles << "), fitted " << rep.fittedVertices
                   << " vertices, unchanged " << rep.unchangedVertices << ", fit E "
                   << rep.fitEnergyBefore << " → " << rep.fitEnergyAfter
                   << ", max |p∞ − original surface| " << rep.maxDeviation);
  REQUIRE(rep.fitEnergyAfter < rep.fitEnergyBefore);
}

// Input vertices farther than `distance` from every vertex of the other mesh are unchanged.
void requireFarVerticesKept(const LoopJoinResult& r, const LoopShape& mine, int side,
                            const LoopShape& other, double distance) {
  std::vector<uint8_t> seen(mine.positions.size(), 0);
  for (uint32_t v = 0; v < r.mesh.positions.size(); ++v)
    if (r.side[v] == side && r.source[v] != kLoopNone && !r.fitted[v]) seen[r.source[v]] = 1;
  size_t far = 0;
  for (uint32_t v = 0; v < mine.positions.size(); ++v) {
    double nearest = 1e300;
    for (const auto& q : other.positions) nearest = std::min(nearest, glm::length(q - mine.positions[v]));
    if (nearest < distance) continue;
    ++far;
    INFO("vertex " << v << " of " << mine.name << ", " << nearest << " from " << other.name);
    REQUIRE(seen[v]);
  }
  REQUIRE(far > mine.positions.size() / 3);
}

}  // namespace

TEST_CASE("Join a sphere and a torus: closed genus-1 manifold, far vertices unchanged",
          "[loop][join]") {
  const LoopShape torus = loopTorus(24, 12, 0.0, 1);
  const LoopShape sphere = placed(loopIcosphere(3), {1.5, 0.0, 0.0}, 0.4);
  LoopJoinResult r = joinLoopMeshes(sphere, torus);
  requireGoodJoin(r, sphere, torus, 0);
  requireFarVerticesKept(r, torus, 1, sphere, 0.6);
  REQUIRE(r.report.maxDeviation < 0.02);
}

TEST_CASE("Join a sphere and a bumpy shape: closed genus-0 manifold", "[loop][join]") {
  const LoopShape bumpy = loopBunny(4, 3);
  const LoopShape sphere = placed(loopIcosphere(3), {0.0, 0.0, -0.9}, 0.45);
  LoopJoinResult r = joinLoopMeshes(bumpy, sphere);
  requireGoodJoin(r, bumpy, sphere, 2);
  requireFarVerticesKept(r, bumpy, 0, sphere, 1.0);  // the bumpy shape's triangles are larger
  REQUIRE(r.report.maxDeviation < 0.02);
}

TEST_CASE("Paste: a part cut from a sphere by a plane, joined into a torus", "[loop][join]") {
  const LoopShape torus = loopTorus(24, 12, 0.0, 1);
  const LoopShape ball = placed(loopIcosphere(3), {1.5, 0.0, 0.0}, 0.4);
  // Keep the outer cap x ≥ 1.15: its rim (radius 0.19 around (1.15, 0, 0)) lies inside the
  // torus's tube (radius 0.35 around the unit circle).
  const LoopShape cap = cutByPlane(ball, {1, 0, 0}, 1.15);
  REQUIRE_FALSE(buildLoopTopology(cap.topology).closed());
  LoopJoinResult r = joinLoopMeshes(cap, torus);
  requireGoodJoin(r, cap, torus, 0);
}

TEST_CASE("Join refuses meshes that do not meet", "[loop][join]") {
  const LoopShape a = loopIcosphere(2);
  const LoopShape b = placed(loopIcosphere(2), {5, 0, 0}, 1.0);
  REQUIRE_THROWS_WITH(joinLoopMeshes(a, b), Catch::Contains("do not intersect"));
}

// 0 levels joins the unrefined meshes (it read unsized refinement flags and crashed); levels
// outside −1..kMaxLoopJoinLevels are refused instead of running without bound.
TEST_CASE("Join with 0 refinement levels on either side; levels out of range refused",
          "[loop][join]") {
  const LoopShape torus = loopTorus(24, 12, 0.0, 1);
  const LoopShape sphere = placed(loopIcosphere(3), {1.5, 0.0, 0.0}, 0.4);
  for (const auto& [levelsA, levelsB] : {std::pair{0, 0}, std::pair{0, -1}, std::pair{-1, 0}}) {
    INFO("levels " << levelsA << "/" << levelsB);
    LoopJoinOptions options;
    options.levelsA = levelsA;
    options.levelsB = levelsB;
    const LoopJoinResult r = joinLoopMeshes(sphere, torus, options);
    if (levelsA == 0) REQUIRE(r.report.levelsA == 0);
    if (levelsB == 0) REQUIRE(r.report.levelsB == 0);
    requireGoodJoin(r, sphere, torus, 0);
  }
  for (const int bad : {-2, kMaxLoopJoinLevels + 1, 1000}) {
    LoopJoinOptions options;
    options.levelsB = bad;
    REQUIRE_THROWS_WITH(joinLoopMeshes(sphere, torus, options),
                        Catch::Contains("levels must be 0.." + std::to_string(kMaxLoopJoinLevels)));
  }
}
