// The leaf walk of the triangulator: each leaf's ring of vertices (its corners and the points
// on its edges) and the triangles over it, for a run of consecutive leaves (leaf_walk.cpp).
// Vertices come out as queries by key, numbered afterwards in leaf order (triangulate.cpp), so
// runs can be walked on several threads and the mesh not depend on how many.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "mesh/detail/line_points.h"
#include "mesh/detail/near_point_merge.h"
#include "mesh/detail/seam_vertices.h"

namespace tessera::triangulate_detail {

// A vertex the leaf walk asks for: its index is handed out after the walk, in the order the
// walk first asked for it, as if it had been looked up then.
struct VertexQuery {
  VertexKey key;
  uint32_t patch;
  glm::vec2 uv;
  uint32_t cover;  // the walk's: how much of the point's neighbourhood the run covers
};

// A triangle of a run: its corners as places in LeafRun::vertices, each corner's (u, v) on the
// leaf's own patch (a welded vertex keeps another patch's), and that patch.
struct RunTriangle {
  std::array<uint32_t, 3> vertex;
  std::array<glm::vec2, 3> uv;
  uint32_t patch;
};

// A run of consecutive leaves, walked. Its distinct vertices are kept in the order the walk
// first asked for them, each with that first query: numbering (triangulate.cpp) looks each key
// up once per run, not once per query (a vertex is asked for by every leaf around it); the
// walk finds a run's own repeats in a table small enough for the cache, on the run's thread.
struct LeafRun {
  std::vector<VertexQuery> vertices;
  // The places in `vertices` whose keys other runs may also ask for, ascending: the rest are
  // points of a patch that this run's leaves surround on all four sides (and no near point is
  // merged into), which no leaf of another run touches: the quad-tree's leaves tile each patch.
  // Only these need the numbering's cross-run lookup.
  std::vector<uint32_t> border;
  std::vector<RunTriangle> triangles;
  size_t droppedTriangles = 0, diagonalFans = 0;

  // Empty, as a new run, keeping its arrays' room (kept_runs.h).
  void clear() {
    vertices.clear();
    border.clear();
    triangles.clear();
    droppedTriangles = diagonalFans = 0;
  }
  size_t capacityBytes() const {
    return vertices.capacity() * sizeof(VertexQuery) + border.capacity() * sizeof(uint32_t) +
           triangles.capacity() * sizeof(RunTriangle);
  }
};

// What the walk reads: set up once, then only looked up (positions included:
// SeamVertices::registerPositions), so several walks may share it.
struct LeafWalkTables {
  SeamVertices& seams;
  const LinePoints& lines;
  const NearPointMerges& merges;
  const HashSet<VertexKey, VertexKeyHash>& mergeTargets;  // the keys near points merge into
};

// Walks leaves [begin, end) into `run`; leaves of patches outside [firstPatch, endPatch) are
// walked without triangles (their vertices are met in the same order as in the whole mesh).
void walkLeaves(const LeafWalkTables& tables, const std::vector<QuadLeaf>& leaves, size_t begin,
                size_t end, uint32_t firstPatch, uint32_t endPatch, LeafRun& run);

}  // namespace tessera::triangulate_detail
