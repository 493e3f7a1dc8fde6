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

namespace {

// Vertices at least `rings` edges away from `start`: a chosen region whose rim is a zigzag of
// edges, not a plane cut.
std::vector<uint32_t> verticesAwayFrom(const LoopShape& s, uint32_t start, uint32_t rings) {
  const LoopTopology t = buildLoopTopology(s.topology);
  std::vector<uint32_t> distance(t.vertexCount, kLoopNone), queue{start};
  distance[start] = 0;
  for (size_t i = 0; i < queue.size(); ++i)
    for (uint32_t j = 0; j < t.valence(queue[i]); ++j) {
      const uint32_t w = t.ring(queue[i])[j];
      if (distance[w] == kLoopNone) distance[w] = distance[queue[i]] + 1, queue.push_back(w);
    }
  std::vector<uint32_t> chosen;
  for (uint32_t v = 0; v < t.vertexCount; ++v)
    if (distance[v] >= rings) chosen.push_back(v);
  return chosen;
}

bool samePosition(const glm::dvec3& a, const glm::dvec3& b) {
  return std::memcmp(&a, &b, sizeof(glm::dvec3)) == 0;
}

}  // namespace

TEST_CASE("Paste by chosen vertices: the part is where the vertices are, joined into a torus",
          "[loop][join]") {
  const LoopShape torus = loopTorus(24, 12, 0.0, 1);
  const LoopShape ball = placed(loopIcosphere(3), {1.5, 0.0, 0.0}, 0.4);
  // Vertex 7 sits in the torus's tube, off the x axis; the ball less its 3-ring reaches into
  // the tube with its rim inside it (data/loop/ball.obj is the same mesh: the CLI test uses
  // this selection).
  REQUIRE(glm::length(ball.positions[7] - glm::dvec3(1.158, 0.131, 0.161)) < 1e-3);
  const std::vector<uint32_t> chosen = verticesAwayFrom(ball, 7, 3);
  REQUIRE(chosen.size() == 74);
  std::vector<uint8_t> isChosen(ball.positions.size(), 0);
  for (uint32_t v : chosen) isChosen[v] = 1;

  const LoopShape part = cutByVertices(ball, chosen);
  const LoopTopology partTopology = buildLoopTopology(part.topology);
  REQUIRE_FALSE(partTopology.closed());
  // Every vertex of the part is a chosen vertex, bit for bit; every triangle of the ball with
  // three chosen corners is in the part.
  size_t wholeTriangles = 0;
  for (size_t f = 0; f < ball.topology.triangles.size() / 3; ++f)
    wholeTriangles += isChosen[ball.topology.triangles[3 * f]] &&
                      isChosen[ball.topology.triangles[3 * f + 1]] &&
                      isChosen[ball.topology.triangles[3 * f + 2]];
  REQUIRE(part.topology.triangles.size() / 3 == wholeTriangles);
  for (const glm::dvec3& p : part.positions) {
    bool found = false;
    for (uint32_t v : chosen) found = found || samePosition(p, ball.positions[v]);
    REQUIRE(found);
  }

  const LoopJoinResult r = joinLoopMeshes(part, torus);
  requireGoodJoin(r, part, torus, 0);  // closed, genus 1, oriented; unfitted vertices kept
  REQUIRE(r.report.maxDeviation < 0.02);
  // No vertex of the ball that was not chosen reaches the result.
  for (uint32_t v = 0; v < ball.positions.size(); ++v)
    if (!isChosen[v])
      for (const glm::dvec3& p : r.mesh.positions) REQUIRE_FALSE(samePosition(p, ball.positions[v]));
  // Most of the part is away from the seam, and there it is the chosen vertices unchanged
  // (requireGoodJoin compared each bit for bit).
  size_t keptFromPart = 0;
  for (uint32_t v = 0; v < r.mesh.positions.size(); ++v)
    keptFromPart += r.side[v] == 0 && !r.fitted[v];
  REQUIRE(keptFromPart > part.positions.size() / 3);
}

TEST_CASE("Paste by chosen vertices: the vertices on one side of a plane give the plane's part",
          "[loop][join]") {
  // The plane mode is the special case of a chosen set: the same triangles and positions.
  const LoopShape ball = placed(loopIcosphere(3), {1.5, 0.0, 0.0}, 0.4);
  std::vector<uint32_t> chosen;
  for (uint32_t v = 0; v < ball.positions.size(); ++v)
    if (ball.positions[v].x >= 1.15) chosen.push_back(v);
  const LoopShape byVertices = cutByVertices(ball, chosen);
  const LoopShape byPlane = cutByPlane(ball, {1, 0, 0}, 1.15);
  REQUIRE(byVertices.topology.triangles == byPlane.topology.triangles);
  REQUIRE(byVertices.positions.size() == byPlane.positions.size());
  for (size_t v = 0; v < byPlane.positions.size(); ++v)
    REQUIRE(samePosition(byVertices.positions[v], byPlane.positions[v]));
}

TEST_CASE("Paste by chosen vertices: out of range, no whole triangle, two pieces refused",
          "[loop][join]") {
  const LoopShape ball = placed(loopIcosphere(3), {1.5, 0.0, 0.0}, 0.4);
  const uint32_t n = uint32_t(ball.positions.size());
  REQUIRE_THROWS_WITH(cutByVertices(ball, {0, n}), Catch::Contains("vertex 92 of") &&
                                                       Catch::Contains("past its 92 vertices"));
  const uint32_t a = ball.topology.triangles[0], b = ball.topology.triangles[1];
  REQUIRE_THROWS_WITH(cutByVertices(ball, {a, b}),
                      Catch::Contains("2 chosen vertices") && Catch::Contains("no whole triangle"));
  // The 1-rings of two vertices far apart: two separate regions.
  std::vector<uint32_t> twoRegions;
  const LoopTopology t = buildLoopTopology(ball.topology);
  uint32_t far = 0;
  for (uint32_t v = 0; v < n; ++v)
    if (glm::length(ball.positions[v] - ball.positions[0]) > glm::length(ball.positions[far] - ball.positions[0]))
      far = v;
  for (uint32_t centre : {0u, far}) {
    twoRegions.push_back(centre);
    for (uint32_t j = 0; j < t.valence(centre); ++j) twoRegions.push_back(t.ring(centre)[j]);
  }
  REQUIRE_THROWS_WITH(cutByVertices(ball, twoRegions),
                      Catch::Contains("are not one piece") && Catch::Contains("one connected region"));
}
