// Watertightness defects of a tessellation, counted against the model's shared patch sides
// (test_tea_set_watertight.cpp, test_screen_tolerance.cpp).
#pragma once
#include <algorithm>

#include "mesh/shared_edges.h"
#include "mesh/tessellate.h"
#include "mesh_checks.h"

namespace tessera::test {

struct WatertightCounts {
  size_t triangles = 0, cracks = 0, tJunctions = 0, overused = 0, inconsistent = 0, degenerate = 0;
  double largestTJunctionEdge = 0;
};

// Open edges off an open side of their own patch are cracks (judged by the triangle's corner
// uvs: a welded vertex keeps another patch's uv), as in test_watertight.cpp's teapot case.
inline WatertightCounts countDefects(const Tessellation& t, const PatchTopology& topology,
                                     double eps) {
  const EdgeCensus c = censusOf(t.mesh, 0.0);
  WatertightCounts counts;
  counts.triangles = t.mesh.triangleCount();
  counts.overused = c.overusedEdges;
  counts.inconsistent = c.inconsistentEdges;
  counts.degenerate = c.degenerateTriangles;
  counts.tJunctions = tJunctionCount(t.mesh, c, eps, &counts.largestTJunctionEdge);
  const auto openSideOf = [&](uint32_t patch, glm::vec2 a, glm::vec2 b) {
    const auto& sides = topology.sides[patch];
    return (a.y == 0.0f && b.y == 0.0f && sides[kSideV0].group < 0) ||
           (a.y == 1.0f && b.y == 1.0f && sides[kSideV1].group < 0) ||
           (a.x == 0.0f && b.x == 0.0f && sides[kSideU0].group < 0) ||
           (a.x == 1.0f && b.x == 1.0f && sides[kSideU1].group < 0);
  };
  for (size_t k = 0; k < t.mesh.indices.size(); ++k) {
    const size_t next = k - k % 3 + (k + 1) % 3;
    const uint32_t a = t.mesh.indices[k], b = t.mesh.indices[next];
    if (c.undirected.at({std::min(a, b), std::max(a, b)}) != 1) continue;
    if (!openSideOf(t.trianglePatch[k / 3], t.cornerUv[k], t.cornerUv[next])) ++counts.cracks;
  }
  return counts;
}

}  // namespace tessera::test
