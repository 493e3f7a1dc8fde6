// The leaf walk of the triangulator: each leaf's ring of vertices (its corners and the points
// on its edges) and the triangles over it, for a run of consecutive leaves (leaf_walk.cpp).
// Vertices come out as queries by key, numbered afterwards in leaf order (triangulate.cpp), so
// runs can be walked on several threads and the mesh not depend on how many.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "common/hash_map.h"
#include "mesh/detail/line_points.h"
#include "mesh/detail/near_point_merge.h"
#include "mesh/detail/seam_vertices.h"

namespace tessera::triangulate_detail {

// A vertex the leaf walk asks for: its index is handed out after the walk, in the order the
// walk asked, as if it had been looked up then.
struct VertexQuery {
  VertexKey key;
  uint32_t patch;
  glm::vec2 uv;
};

// A run of consecutive leaves, walked: their vertex queries in order, and their triangles
// as positions in `queries`.
struct LeafRun {
  std::vector<VertexQuery> queries;
  std::vector<std::array<uint32_t, 3>> triangles;
  size_t droppedTriangles = 0, diagonalFans = 0;
  // The queries that are the first of their key in this run, in order; per query, its
  // key's place in `firsts`; per first query, its vertex index (numbered after the walk).
  std::vector<uint32_t> firsts, first, ids;

  // Numbering looks each key up once per run, not once per query (a vertex is asked for by
  // every leaf around it), here in a table small enough for the cache, on the run's thread.
  void findFirsts() {
    HashMap<VertexKey, uint32_t, VertexKeyHash> place;
    place.reserve(queries.size());
    first.resize(queries.size());
    for (size_t q = 0; q < queries.size(); ++q) {
      const auto [k, added] = place.try_emplace(queries[q].key, uint32_t(firsts.size()));
      if (added) firsts.push_back(uint32_t(q));
      first[q] = k->second;
    }
  }
};

// What the walk reads: set up once, then only looked up (positions included:
// SeamVertices::registerPositions), so several walks may share it.
struct LeafWalkTables {
  SeamVertices& seams;
  const LinePoints& lines;
  const NearPointMerges& merges;
};

// Walks leaves [begin, end) into `run`; leaves of patches outside [firstPatch, endPatch) are
// walked without triangles (their vertices are met in the same order as in the whole mesh).
void walkLeaves(const LeafWalkTables& tables, const std::vector<QuadLeaf>& leaves, size_t begin,
                size_t end, uint32_t firstPatch, uint32_t endPatch, LeafRun& run);

}  // namespace tessera::triangulate_detail
