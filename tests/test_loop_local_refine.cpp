// Local Loop refinement with T-node splits (host/loop/local_refine.h, the paper's figure 6):
// split faces become 4, a neighbour with k split edges becomes 1 + k triangles (1 → 2, 2 → 3,
// 3 → the regular 4), new vertices by Loop's edge mask, old vertices bit for bit, and the
// result stays a closed oriented 2-manifold with the same Euler characteristic.
#include <catch2/catch.hpp>

#include <cstring>

#include "loop/local_refine.h"
#include "loop/refine.h"

using namespace tessera;

TEST_CASE("Local refinement: T-node splits 1→2, 2→3, 3→4 and Loop edge points", "[loop][join]") {
  const LoopShape shape = loopBunny(3, 2);
  const LoopTopology t = buildLoopTopology(shape.topology);
  // A fixed pattern of faces, plus the three neighbours of face 1 (not face 1 itself), so
  // that unsplit faces with 1, 2 and 3 split edges all occur.
  std::vector<uint8_t> split(t.faceCount(), 0);
  for (size_t f = 0; f < t.faceCount(); ++f) split[f] = (f * 7) % 5 == 0;
  split[1] = 0;
  for (int i = 0; i < 3; ++i) {
    const auto& faces = t.edgeFaces[t.faceEdges[3 + i]];
    split[faces[0] == 1 ? faces[1] : faces[0]] = 1;
  }
  std::vector<uint8_t> edgeSplit(t.edgeCount(), 0);
  for (size_t f = 0; f < t.faceCount(); ++f)
    if (split[f])
      for (int i = 0; i < 3; ++i) edgeSplit[t.faceEdges[3 * f + i]] = 1;
  size_t expectedFaces = 0, withTNodes[4] = {0, 0, 0, 0};
  for (size_t f = 0; f < t.faceCount(); ++f) {
    int k = 0;
    for (int i = 0; i < 3; ++i) k += edgeSplit[t.faceEdges[3 * f + i]];
    expectedFaces += split[f] ? 4 : 1 + k;
    if (!split[f]) ++withTNodes[k];
  }
  INFO("faces with 1, 2, 3 T-nodes: " << withTNodes[1] << ", " << withTNodes[2] << ", " << withTNodes[3]);
  REQUIRE(withTNodes[1] > 0);
  REQUIRE(withTNodes[2] > 0);
  REQUIRE(withTNodes[3] > 0);

  const LocalRefinement r = refineLocally(shape, split);
  const LoopTopology fine = buildLoopTopology(r.mesh.topology);  // throws unless a 2-manifold
  REQUIRE(fine.closed());
  REQUIRE(fine.faceCount() == expectedFaces);
  size_t newVertices = 0;
  for (uint8_t s : edgeSplit) newVertices += s;
  REQUIRE(fine.vertexCount == t.vertexCount + newVertices);
  const long euler = long(t.vertexCount) - long(t.edgeCount()) + long(t.faceCount());
  REQUIRE(long(fine.vertexCount) - long(fine.edgeCount()) + long(fine.faceCount()) == euler);
  REQUIRE(signedVolume(r.mesh) > 0);
  for (uint32_t v = 0; v < t.vertexCount; ++v)
    REQUIRE(std::memcmp(&r.mesh.positions[v], &shape.positions[v], sizeof(glm::dvec3)) == 0);
  // New vertices in edge order, each at Loop's 3/8, 3/8, 1/8, 1/8 point, flagged as refined.
  LoopMask mask;
  uint32_t next = t.vertexCount;
  std::vector<uint32_t> vertexOfEdge(t.edgeCount(), kLoopNone);
  for (size_t f = 0; f < t.faceCount(); ++f)
    if (split[f])
      for (int i = 0; i < 3; ++i) {
        const uint32_t e = t.faceEdges[3 * f + i];
        if (vertexOfEdge[e] == kLoopNone) vertexOfEdge[e] = next++;
      }
  for (uint32_t e = 0; e < t.edgeCount(); ++e) {
    if (vertexOfEdge[e] == kLoopNone) continue;
    loopEdgeMask(t, e, mask);
    REQUIRE(r.mesh.positions[vertexOfEdge[e]] == mask.apply(shape.positions));
    REQUIRE(r.refined[vertexOfEdge[e]] == 1);
    // The new vertex sits on both halves of its edge.
    REQUIRE(fine.edgeBetween(vertexOfEdge[e], t.edgeVertices[e][0]) != kLoopNone);
    REQUIRE(fine.edgeBetween(vertexOfEdge[e], t.edgeVertices[e][1]) != kLoopNone);
  }
}

TEST_CASE("Local refinement of nothing and of everything", "[loop][join]") {
  const LoopShape shape = loopIcosphere(2);
  const LoopTopology t = buildLoopTopology(shape.topology);
  const LocalRefinement none = refineLocally(shape, std::vector<uint8_t>(t.faceCount(), 0));
  REQUIRE(none.mesh.topology.triangles == shape.topology.triangles);
  // Splitting every face is one level of uniform Loop topology (even vertices not smoothed).
  const LocalRefinement all = refineLocally(shape, std::vector<uint8_t>(t.faceCount(), 1));
  const LoopTopology fine = buildLoopTopology(all.mesh.topology);
  REQUIRE(fine.faceCount() == 4 * t.faceCount());
  REQUIRE(fine.vertexCount == t.vertexCount + t.edgeCount());
  REQUIRE_THROWS_WITH(refineLocally(shape, {1, 0}), Catch::Contains("2 flags for 80 faces"));
}
