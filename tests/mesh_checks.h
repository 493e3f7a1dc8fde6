// Topological checks of triangle meshes for the watertightness tests.
#pragma once
#include <cstdint>
#include <map>
#include <utility>

#include "mesh/mesh.h"

namespace tessera::test {

struct EdgeCensus {
  std::map<std::pair<uint32_t, uint32_t>, int> directed;    // (a, b) → times used a→b
  std::map<std::pair<uint32_t, uint32_t>, int> undirected;  // (min, max) → times used
  size_t boundaryEdges = 0;      // used by one triangle
  size_t manifoldEdges = 0;      // used by two
  size_t overusedEdges = 0;      // used by three or more
  size_t inconsistentEdges = 0;  // used twice in the same direction
  size_t degenerateTriangles = 0;
  size_t usedVertices = 0;
};

inline EdgeCensus censusOf(const TriangleMesh& mesh, double minArea) {
  EdgeCensus c;
  std::map<uint32_t, bool> used;
  for (size_t t = 0; t < mesh.indices.size(); t += 3) {
    uint32_t v[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
    glm::dvec3 a(mesh.positions[v[0]]), b(mesh.positions[v[1]]), d(mesh.positions[v[2]]);
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2] ||
        0.5 * glm::length(glm::cross(b - a, d - a)) <= minArea)
      ++c.degenerateTriangles;
    for (int k = 0; k < 3; ++k) {
      uint32_t p = v[k], q = v[(k + 1) % 3];
      used[p] = true;
      ++c.directed[{p, q}];
      ++c.undirected[{std::min(p, q), std::max(p, q)}];
    }
  }
  for (const auto& [edge, count] : c.undirected) {
    if (count == 1) ++c.boundaryEdges;
    if (count == 2) {
      ++c.manifoldEdges;
      if (c.directed[{edge.first, edge.second}] != 1) ++c.inconsistentEdges;
    }
    if (count > 2) ++c.overusedEdges;
  }
  c.usedVertices = used.size();
  return c;
}

}  // namespace tessera::test
