// Loop topology: edges, rings, vertex rules, refinement counts, and a clear error for each kind
// of input it rejects.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "loop/shapes.h"
#include "loop/topology.h"

using namespace tessera;

namespace {

LoopControlTopology triangles(uint32_t vertexCount, std::vector<uint32_t> indices) {
  LoopControlTopology c;
  c.vertexCount = vertexCount;
  c.triangles = std::move(indices);
  return c;
}

std::string errorOf(const LoopControlTopology& c) {
  try {
    buildLoopTopology(c);
  } catch (const LoopTopologyError& e) {
    return e.what();
  }
  return "";
}

// For every face (a, b, c), b is followed by c in a's ring (cyclically for interior vertices).
void requireCounterClockwiseRings(const LoopTopology& t) {
  for (size_t f = 0; f < t.faceCount(); ++f)
    for (int i = 0; i < 3; ++i) {
      const uint32_t a = t.triangles[3 * f + i], b = t.triangles[3 * f + (i + 1) % 3],
                     c = t.triangles[3 * f + (i + 2) % 3];
      const uint32_t k = t.valence(a);
      const uint32_t* ring = t.ring(a);
      const uint32_t at = uint32_t(std::find(ring, ring + k, b) - ring);
      REQUIRE(at < k);
      const uint32_t next = t.vertexBoundary[a] ? at + 1 : (at + 1) % k;
      REQUIRE(next < k);
      REQUIRE(ring[next] == c);
    }
}

}  // namespace

TEST_CASE("Loop topology of a tetrahedron: 6 edges, closed, valence 3, smooth", "[loop]") {
  LoopShape s = loopTetrahedron();
  LoopTopology t = buildLoopTopology(s.topology);
  REQUIRE(t.edgeCount() == 6);
  REQUIRE(t.closed());
  for (uint32_t v = 0; v < 4; ++v) {
    REQUIRE(t.valence(v) == 3);
    REQUIRE(t.faceValence(v) == 3);
    REQUIRE(t.vertexRule[v] == LoopVertexRule::Smooth);
  }
  requireCounterClockwiseRings(t);
  REQUIRE(signedVolume(s) > 0);
}

TEST_CASE("Loop topology of an open grid: boundaries, corners and crease rules", "[loop]") {
  LoopShape s = loopGrid(4, 3, 1);
  LoopTopology t = buildLoopTopology(s.topology);
  REQUIRE(t.faceCount() == 12);
  // 3 horizontal edges in each of 3 rows, 4 vertical in each of 2 rows, one diagonal per quad.
  REQUIRE(t.edgeCount() == 3 * 3 + 4 * 2 + 3 * 2);
  REQUIRE_FALSE(t.closed());
  requireCounterClockwiseRings(t);
  auto id = [](int i, int j) { return uint32_t(j * 4 + i); };
  // (3, 0) and (0, 2) lie in one triangle each: corners; (0, 0) and (3, 2) in two: crease.
  REQUIRE(t.vertexRule[id(3, 0)] == LoopVertexRule::Corner);
  REQUIRE(t.vertexRule[id(0, 2)] == LoopVertexRule::Corner);
  REQUIRE(t.vertexRule[id(0, 0)] == LoopVertexRule::Crease);
  REQUIRE(t.vertexRule[id(3, 2)] == LoopVertexRule::Crease);
  REQUIRE(t.vertexRule[id(1, 0)] == LoopVertexRule::Crease);
  REQUIRE(t.vertexRule[id(1, 1)] == LoopVertexRule::Smooth);
  REQUIRE(t.vertexBoundary[id(1, 0)]);
  REQUIRE_FALSE(t.vertexBoundary[id(1, 1)]);
  // A boundary ring runs from one boundary neighbour to the other.
  REQUIRE(t.valence(id(1, 0)) == t.faceValence(id(1, 0)) + 1);
  const uint32_t* ring = t.ring(id(1, 0));
  REQUIRE(ring[0] == id(2, 0));
  REQUIRE(ring[t.valence(id(1, 0)) - 1] == id(0, 0));
}

TEST_CASE("Loop topology: creases and marked corners set the vertex rules", "[loop]") {
  LoopTopology cube = buildLoopTopology(loopCreasedCube().topology);
  REQUIRE(cube.closed());
  REQUIRE(std::count(cube.edgeCrease.begin(), cube.edgeCrease.end(), 1) == 12);
  for (uint32_t v = 0; v < 8; ++v) REQUIRE(cube.vertexRule[v] == LoopVertexRule::Corner);

  LoopShape sphere = loopCreasedSphere(2, 3);
  LoopTopology t = buildLoopTopology(sphere.topology);
  REQUIRE(sphere.topology.creases.size() == 3);
  const auto& path = sphere.topology.creases;
  REQUIRE(t.vertexRule[path[0][0]] == LoopVertexRule::Dart);
  REQUIRE(t.vertexRule[path[1][0]] == LoopVertexRule::Crease);
  REQUIRE(t.vertexRule[path[2][0]] == LoopVertexRule::Crease);
  REQUIRE(t.vertexRule[path[2][1]] == LoopVertexRule::Dart);
  REQUIRE(t.vertexRule[sphere.topology.corners[0]] == LoopVertexRule::Corner);
}

TEST_CASE("Loop topology: refinement counts, inherited creases and regular odd vertices",
          "[loop]") {
  for (const LoopShape& s : {loopBunny(2, 7), loopGrid(5, 4, 2), loopCreasedCube()}) {
    INFO(s.name);
    LoopTopology coarse = buildLoopTopology(s.topology);
    LoopTopology fine = refineLoopTopology(coarse);
    REQUIRE(fine.vertexCount == coarse.vertexCount + coarse.edgeCount());
    REQUIRE(fine.faceCount() == 4 * coarse.faceCount());
    REQUIRE(fine.edgeCount() == 2 * coarse.edgeCount() + 3 * coarse.faceCount());
    const long euler = long(coarse.vertexCount) - long(coarse.edgeCount()) + long(coarse.faceCount());
    REQUIRE(long(fine.vertexCount) - long(fine.edgeCount()) + long(fine.faceCount()) == euler);
    REQUIRE(fine.closed() == coarse.closed());
    requireCounterClockwiseRings(fine);
    for (uint32_t v = 0; v < coarse.vertexCount; ++v) {
      REQUIRE(fine.valence(v) == coarse.valence(v));
      REQUIRE(fine.vertexRule[v] == coarse.vertexRule[v]);
    }
    for (uint32_t e = 0; e < coarse.edgeCount(); ++e) {
      const uint32_t odd = coarse.vertexCount + e;
      const bool boundary = coarse.edgeFaces[e][1] == kLoopNone;
      REQUIRE(fine.valence(odd) == (boundary ? 4u : 6u));
      const bool crease = coarse.edgeCrease[e];
      REQUIRE(fine.vertexRule[odd] ==
              (crease || boundary ? LoopVertexRule::Crease : LoopVertexRule::Smooth));
    }
    REQUIRE(std::count(fine.edgeCrease.begin(), fine.edgeCrease.end(), 1) ==
            2 * std::count(coarse.edgeCrease.begin(), coarse.edgeCrease.end(), 1));
  }
}

TEST_CASE("Loop topology: the bunny-like mesh has irregular valences 3 to 9", "[loop]") {
  LoopTopology t = buildLoopTopology(loopBunny(4, 11).topology);
  REQUIRE(t.closed());
  uint32_t lo = 100, hi = 0;
  for (uint32_t v = 0; v < t.vertexCount; ++v) lo = std::min(lo, t.valence(v)), hi = std::max(hi, t.valence(v));
  CHECK(lo <= 4);
  CHECK(hi >= 8);
  REQUIRE(lo >= 3);
  REQUIRE(hi <= 9);
}

TEST_CASE("Loop topology rejects bad input with a message naming the culprit", "[loop]") {
  using Catch::Matchers::Contains;
  // Three triangles on edge (0, 1).
  CHECK_THAT(errorOf(triangles(5, {0, 1, 2, 1, 0, 3, 0, 1, 4})), Contains("non-manifold"));
  CHECK_THAT(errorOf(triangles(5, {0, 1, 2, 1, 0, 3, 1, 0, 4})), Contains("shared by 3"));
  // Two triangles running along (0, 1) the same way.
  CHECK_THAT(errorOf(triangles(4, {0, 1, 2, 0, 1, 3})), Contains("not consistently oriented"));
  // A bow tie: two triangles sharing only vertex 0.
  CHECK_THAT(errorOf(triangles(5, {0, 1, 2, 0, 3, 4})), Contains("vertex 0 is non-manifold"));
  // Two closed cones sharing their apex.
  {
    LoopShape a = loopTetrahedron();
    std::vector<uint32_t> both = a.topology.triangles;
    for (uint32_t i : a.topology.triangles) both.push_back(i == 0 ? 0 : i + 3);
    CHECK_THAT(errorOf(triangles(7, both)), Contains("vertex 0 is non-manifold"));
  }
  CHECK_THAT(errorOf(triangles(4, {0, 1, 2})), Contains("vertex 3 is used by no triangle"));
  // The same triangle twice, opposite orientations: every edge has two faces, consistently
  // oriented, but the refined mesh would be no manifold: refused here, not in refinement.
  CHECK_THAT(errorOf(triangles(3, {0, 1, 2, 0, 2, 1})),
             Contains("triangles 0 and 1 are the same triangle in opposite orientations"));
  CHECK_THAT(errorOf(triangles(3, {0, 1, 5})), Contains("triangle 0 uses vertex 5"));
  CHECK_THAT(errorOf(triangles(3, {0, 1, 1})), Contains("repeats a vertex"));
  CHECK_THAT(errorOf(triangles(3, {0, 1})), Contains("not a multiple of 3"));
  CHECK_THAT(errorOf(triangles(0, {})), Contains("no triangles"));
  LoopControlTopology crease = triangles(4, {0, 1, 2, 0, 2, 3});
  crease.creases = {{1, 3}};
  CHECK_THAT(errorOf(crease), Contains("crease (1, 3) is not an edge"));
  LoopControlTopology corner = triangles(3, {0, 1, 2});
  corner.corners = {7};
  CHECK_THAT(errorOf(corner), Contains("corner vertex 7"));
  try {
    buildLoopTopology(triangles(4, {0, 1, 2, 0, 1, 3}));
    FAIL("no error");
  } catch (const LoopTopologyError& e) {
    // The later triangle: the first one fixed the edge's direction, the second contradicts it.
    REQUIRE(e.face() == 1);
  }
}
