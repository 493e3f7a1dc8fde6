// Caps (three corners on one fp32 line) flipped away without opening the mesh
// (host/mesh/zero_area.h).
#include <catch2/catch.hpp>

#include <algorithm>

#include "mesh/zero_area.h"
#include "mesh_checks.h"

using namespace tessera;

namespace {

struct Flipped {
  std::vector<uint32_t> indices;
  std::vector<bool> removed;
  std::vector<uint32_t> patches;
  std::vector<glm::vec2> uvs;
};

Flipped flip(const std::vector<glm::vec3>& positions, std::vector<uint32_t> indices,
             unsigned threads = 1) {
  Flipped f;
  const size_t count = indices.size() / 3;
  f.patches.assign(count, 0);
  for (size_t t = 0; t < count; ++t) f.patches[t] = uint32_t(t);
  for (uint32_t v : indices) f.uvs.push_back(glm::vec2(positions[v]));
  f.removed = removeCaps(positions, indices, f.patches, f.uvs, threads);
  for (size_t t = 0; t < count; ++t)
    if (!f.removed[t]) f.indices.insert(f.indices.end(), &indices[3 * t], &indices[3 * t + 3]);
  return f;
}

}  // namespace

TEST_CASE("a cap is flipped into its neighbour across the long edge", "[watertight]") {
  // A square 0-1-2-3 cut along 0–2, with vertex 4 on the diagonal: triangles (0, 4, 2) is a
  // cap; (0, 2, 3) the neighbour across its long edge; (0, 1, 4) and (4, 1, 2) fill the rest.
  const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5f, 0.5f, 0}};
  const std::vector<uint32_t> before = {0, 1, 4, 4, 1, 2, 0, 4, 2, 2, 3, 0};
  TriangleMesh mesh;
  mesh.positions = p;
  mesh.indices = before;
  REQUIRE(test::censusOf(mesh, 0.0).degenerateTriangles == 1);
  const Flipped f = flip(p, before);
  REQUIRE(f.indices.size() == before.size());  // the cap and its neighbour became two others
  mesh.indices = f.indices;
  const test::EdgeCensus c = test::censusOf(mesh, 0.0);
  REQUIRE(c.degenerateTriangles == 0);
  REQUIRE(c.inconsistentEdges == 0);
  REQUIRE(c.overusedEdges == 0);
  REQUIRE(c.boundaryEdges == 4);  // still the square's outline: closed inside
  // The pair took the neighbour's patch; the middle vertex's (u, v) is interpolated.
  REQUIRE(f.patches[2] == 3);
  REQUIRE(f.patches[3] == 3);
  REQUIRE(f.uvs[6].x == Approx(0.5f));
}

TEST_CASE("a cap on an open edge goes, and the boundary runs through its middle", "[watertight]") {
  // (0, 1, 2) is a cap on the open edge 0–1 (vertex 2 on it); (2, 1, 3) and (0, 2, 3) above.
  const std::vector<glm::vec3> p = {{0, 0, 0}, {2, 0, 0}, {1, 0, 0}, {1, 1, 0}};
  const Flipped f = flip(p, {0, 1, 2, 2, 1, 3, 0, 2, 3});
  REQUIRE(f.removed == std::vector<bool>{true, false, false});
  TriangleMesh mesh;
  mesh.positions = p;
  mesh.indices = f.indices;
  const test::EdgeCensus c = test::censusOf(mesh, 0.0);
  REQUIRE(c.degenerateTriangles == 0);
  REQUIRE(c.boundaryEdges == 4);
  REQUIRE(test::tJunctionCount(mesh, c, 1e-6) == 0);
}

TEST_CASE("two caps over one edge become caps over shorter ones, then flip away",
          "[watertight]") {
  // A strip of zero width along the x axis: (0, 4, 1) and (1, 5, 0) are caps over the same
  // edge 0–1 (vertices 4 and 5 inside it), closed by triangles off the line above (over 0–4
  // and 4–1) and below (over 1–5 and 5–0).
  const std::vector<glm::vec3> p = {{0, 0, 0}, {3, 0, 0}, {1.5f, 2, 0},
                                    {1.5f, -2, 0}, {1, 0, 0}, {2, 0, 0}};
  const std::vector<uint32_t> mesh = {0, 4, 1, 1, 5, 0, 4, 2, 1, 0, 2, 4, 5, 1, 3, 0, 5, 3};
  const Flipped f = flip(p, mesh);
  TriangleMesh m;
  m.positions = p;
  m.indices = f.indices;
  const test::EdgeCensus c = test::censusOf(m, 0.0);
  REQUIRE(f.indices.size() == mesh.size());
  REQUIRE(c.degenerateTriangles == 0);
  REQUIRE(c.overusedEdges == 0);
  REQUIRE(c.inconsistentEdges == 0);
  REQUIRE(c.boundaryEdges == 4);
}

TEST_CASE("caps are found and flipped the same on any thread count", "[watertight][threads]") {
  // A 120 × 120 grid of two triangles a cell (28,800 triangles: looked for on several threads)
  // with every 7th vertex of every 5th row moved down onto the row below, half a cell right: the
  // triangle of the cell to its lower left with two corners on that row is then a cap (three
  // distinct points on one line), flipped or removed the same whatever the thread count.
  const int n = 120;
  std::vector<glm::vec3> p;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) p.push_back({float(i), float(j), 0.0f});
  for (int j = 5; j <= n; j += 5)
    for (int i = 3; i < n; i += 7) p[size_t(j * (n + 1) + i)] = {float(i) + 0.5f, float(j - 1), 0.0f};
  std::vector<uint32_t> mesh;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n) + 2,
                     d = a + uint32_t(n) + 1;
      mesh.insert(mesh.end(), {a, b, c, a, c, d});
    }
  const Flipped one = flip(p, mesh, 1);
  REQUIRE(one.indices != mesh);  // caps were there, and went or flipped
  REQUIRE(std::count(one.removed.begin(), one.removed.end(), true) < 100);
  for (unsigned threads : {2u, 3u, 0u}) {
    INFO(threads << " threads");
    const Flipped many = flip(p, mesh, threads);
    REQUIRE(many.removed == one.removed);
    REQUIRE(many.indices == one.indices);
    REQUIRE(many.patches == one.patches);
    REQUIRE(many.uvs == one.uvs);
  }
}
