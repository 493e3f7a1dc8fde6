// Loop's refinement rules, each checked on a mesh small enough to compute by hand: β, the
// odd-vertex 3/8-3/8-1/8-1/8 mask, the even-vertex mask for valences 3 to 9, boundary edges,
// boundary vertices, corners and creases.
#include <catch2/catch.hpp>

#include <cmath>

#include "loop/refine.h"
#include "loop/shapes.h"

using namespace tessera;

namespace {

double distance(const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b); }

}  // namespace

TEST_CASE("Loop beta: 3/16 at valence 3, 1/16 at 6, Loop's formula elsewhere", "[loop]") {
  REQUIRE(loopBeta(3) == 3.0 / 16.0);
  // The general formula gives 3/16 at k = 3 as well: the two cases of the paper's (1) agree.
  const double c3 = 3.0 / 8.0 + 0.25 * std::cos(2.0 * M_PI / 3.0);
  REQUIRE((5.0 / 8.0 - c3 * c3) / 3.0 == Approx(3.0 / 16.0).epsilon(1e-15));
  REQUIRE(loopBeta(6) == Approx(1.0 / 16.0).epsilon(1e-15));
  REQUIRE(loopBeta(4) == Approx((5.0 / 8.0 - (3.0 / 8.0) * (3.0 / 8.0)) / 4.0).epsilon(1e-15));
  const double c5 = 3.0 / 8.0 + 0.25 * std::cos(2.0 * M_PI / 5.0);
  REQUIRE(loopBeta(5) == Approx((5.0 / 8.0 - c5 * c5) / 5.0).epsilon(1e-15));
}

TEST_CASE("Loop refinement of a tetrahedron by hand", "[loop]") {
  LoopShape s = loopTetrahedron();
  LoopTopology t = buildLoopTopology(s.topology);
  auto fine = refineLoopPositions(t, s.positions);
  REQUIRE(fine.size() == 10);
  // Even vertex (valence 3): (1 − 3·3/16) p + 3/16 Σ neighbours = 7/16 p + 3/16 (sum − p).
  glm::dvec3 sum = s.positions[0] + s.positions[1] + s.positions[2] + s.positions[3];
  for (uint32_t v = 0; v < 4; ++v)
    REQUIRE(distance(fine[v], 7.0 / 16.0 * s.positions[v] + 3.0 / 16.0 * (sum - s.positions[v])) <
            1e-15);
  // Odd vertex: 3/8 of its ends, 1/8 of the two others.
  for (uint32_t e = 0; e < 6; ++e) {
    const auto [a, b] = t.edgeVertices[e];
    const glm::dvec3 ends = s.positions[a] + s.positions[b];
    REQUIRE(distance(fine[4 + e], 3.0 / 8.0 * ends + 1.0 / 8.0 * (sum - ends)) < 1e-15);
  }
}

TEST_CASE("Loop even-vertex rule for valences 3 to 9 on the bunny-like mesh", "[loop]") {
  LoopShape s = loopBunny(3, 5);
  LoopTopology t = buildLoopTopology(s.topology);
  auto fine = refineLoopPositions(t, s.positions);
  std::vector<int> seen(10, 0);
  for (uint32_t v = 0; v < t.vertexCount; ++v) {
    const uint32_t k = t.valence(v);
    glm::dvec3 ring(0.0);
    for (uint32_t j = 0; j < k; ++j) ring += s.positions[t.ring(v)[j]];
    const double beta = loopBeta(k);
    REQUIRE(distance(fine[v], (1.0 - k * beta) * s.positions[v] + beta * ring) < 1e-14);
    ++seen[k];
  }
  for (uint32_t k = 3; k <= 8; ++k) CHECK(seen[k] > 0);
}

TEST_CASE("Loop boundary rules: edges ½ ½, vertices ⅛ ¾ ⅛, single-triangle corners fixed",
          "[loop]") {
  LoopShape s = loopGrid(4, 3, 3);
  LoopTopology t = buildLoopTopology(s.topology);
  auto fine = refineLoopPositions(t, s.positions);
  auto id = [](int i, int j) { return uint32_t(j * 4 + i); };
  const auto& p = s.positions;
  // Boundary vertex (1, 0): neighbours (0, 0) and (2, 0) along the boundary.
  REQUIRE(distance(fine[id(1, 0)], 0.75 * p[id(1, 0)] + 0.125 * (p[id(0, 0)] + p[id(2, 0)])) < 1e-15);
  // (0, 0) lies in two triangles: a crease vertex too, between (1, 0) and (0, 1).
  REQUIRE(distance(fine[id(0, 0)], 0.75 * p[id(0, 0)] + 0.125 * (p[id(1, 0)] + p[id(0, 1)])) < 1e-15);
  REQUIRE(fine[id(3, 0)] == p[id(3, 0)]);
  REQUIRE(fine[id(0, 2)] == p[id(0, 2)]);
  for (uint32_t e = 0; e < t.edgeCount(); ++e) {
    const auto [a, b] = t.edgeVertices[e];
    if (t.edgeFaces[e][1] == kLoopNone)
      REQUIRE(distance(fine[t.vertexCount + e], 0.5 * (p[a] + p[b])) < 1e-15);
    else
      REQUIRE(distance(fine[t.vertexCount + e],
                       0.375 * (p[a] + p[b]) +
                           0.125 * (p[t.oppositeVertex(e, t.edgeFaces[e][0])] +
                                    p[t.oppositeVertex(e, t.edgeFaces[e][1])])) < 1e-15);
  }
  // An interior vertex keeps the smooth rule next to the boundary.
  const uint32_t v = id(1, 1);
  glm::dvec3 ring(0.0);
  for (uint32_t j = 0; j < t.valence(v); ++j) ring += p[t.ring(v)[j]];
  REQUIRE(distance(fine[v], (1 - 6 * loopBeta(6)) * p[v] + loopBeta(6) * ring) < 1e-15);
}

TEST_CASE("Loop creases: a creased cube keeps its corners and its edges stay straight",
          "[loop]") {
  LoopShape s = loopCreasedCube();
  LoopLevels levels = refineLoop(buildLoopTopology(s.topology), s.positions, 3);
  const LoopTopology& t = levels.topology.back();
  const auto& p = levels.positions.back();
  for (uint32_t v = 0; v < 8; ++v) REQUIRE(p[v] == s.positions[v]);
  // Every crease vertex lies on a cube edge: two of its coordinates are 0 or 1.
  size_t creaseVertices = 0;
  for (uint32_t v = 0; v < t.vertexCount; ++v) {
    if (t.vertexRule[v] != LoopVertexRule::Crease) continue;
    ++creaseVertices;
    int onFace = 0;
    for (int c = 0; c < 3; ++c) onFace += (p[v][c] == 0.0 || p[v][c] == 1.0);
    REQUIRE(onFace >= 2);
  }
  REQUIRE(creaseVertices == 12 * 7);  // 2³ − 1 new vertices on each of the 12 edges
  // Interior vertices have moved inside the cube.
  for (uint32_t v = 0; v < t.vertexCount; ++v)
    for (int c = 0; c < 3; ++c) REQUIRE((p[v][c] >= 0.0 && p[v][c] <= 1.0));
}

TEST_CASE("Loop crease vertex on a sphere: ⅛ ¾ ⅛ along the crease, darts smooth", "[loop]") {
  LoopShape s = loopCreasedSphere(3, 4);
  LoopTopology t = buildLoopTopology(s.topology);
  auto fine = refineLoopPositions(t, s.positions);
  const auto& path = s.topology.creases;
  const auto& p = s.positions;
  for (size_t i = 1; i < path.size(); ++i) {
    const uint32_t v = path[i][0];
    REQUIRE(t.vertexRule[v] == LoopVertexRule::Crease);
    REQUIRE(distance(fine[v], 0.75 * p[v] + 0.125 * (p[path[i - 1][0]] + p[path[i][1]])) < 1e-15);
  }
  const uint32_t dart = path[0][0];
  glm::dvec3 ring(0.0);
  const uint32_t k = t.valence(dart);
  for (uint32_t j = 0; j < k; ++j) ring += p[t.ring(dart)[j]];
  REQUIRE(distance(fine[dart], (1 - k * loopBeta(k)) * p[dart] + loopBeta(k) * ring) < 1e-15);
  const uint32_t corner = s.topology.corners[0];
  REQUIRE(fine[corner] == p[corner]);
}

TEST_CASE("Loop masks are affine: weights sum to 1 at every level", "[loop]") {
  for (const LoopShape& s : {loopBunny(2, 3), loopGrid(5, 5, 1), loopCreasedSphere(2, 3)}) {
    LoopTopology t = buildLoopTopology(s.topology);
    LoopMask mask;
    for (int level = 0; level < 2; ++level) {
      for (uint32_t v = 0; v < t.vertexCount; ++v) {
        loopVertexMask(t, v, mask);
        double sum = 0;
        for (double w : mask.weights) sum += w;
        REQUIRE(sum == Approx(1.0).epsilon(1e-15));
      }
      for (uint32_t e = 0; e < t.edgeCount(); ++e) {
        loopEdgeMask(t, e, mask);
        double sum = 0;
        for (double w : mask.weights) sum += w;
        REQUIRE(sum == 1.0);
      }
      t = refineLoopTopology(t);
    }
  }
}
