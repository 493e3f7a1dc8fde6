// triangulateLeaves (triangulate.h): a one-leaf tree directly (one_leaf.cpp); else sets up
// what a leaf's vertices are (seam_vertices.cpp, line_points.cpp, near_point_merge.cpp), walks the leaves in runs on threads
// (leaf_walk.cpp), and numbers the vertices the walk asked for in leaf order, as one walk
// would have, so that the mesh does not depend on the thread count.
#include "mesh/triangulate.h"

#include <optional>
#include <utility>

#include "common/hash_map.h"
#include "common/parallel_for.h"
#include "mesh/detail/kept_runs.h"
#include "mesh/detail/leaf_walk.h"
#include "mesh/detail/one_leaf.h"
#include "mesh/detail/run_places.h"

namespace tessera {

using namespace triangulate_detail;

namespace {
constexpr size_t kKeptBorderKeys = size_t(1) << 15;  // 2¹⁷ slots at most: 3 MiB
constexpr size_t kRunsForSecondThread = 24;          // the numbering's (below)

// Sets up what a leaf's vertices are (seam_vertices.cpp, line_points.cpp,
// near_point_merge.cpp) and walks the leaves into `runs`, `runLength` leaves a run. The lines,
// their near pairs and the merges serve the walk only: they end with this call, before the
// numbering allocates the mesh (~1 GiB at 10⁶ patches, as much as the runs and the mesh).
void walkLeafRuns(const std::vector<QuadLeaf>& leaves, const PatchTopology& topology,
                  SeamVertices& seams, const TriangulationScope& scope, size_t runLength,
                  std::vector<LeafRun>& runs) {
  // Each set's near pairs are found on a thread that filled it: a worker's wake-up (~40 µs)
  // costs about what a small tree's search takes.
  LinePairs pairsU, pairsV;
  std::optional<SharedSidePairs> pairsShared(std::in_place, topology.groupCount);
  LinePoints lines =
      collectLinePoints(leaves, seams, scope.threads, [&](LinePoints& filled, LineSet set) {
        if (set == LineSet::kAlongU)
          pairsU = findLinePairs(filled.alongU, seams, true);
        else if (set == LineSet::kAlongV)
          pairsV = findLinePairs(filled.alongV, seams, false);
        else
          pairsShared->findUntaken(filled, seams);
      });
  for (uint32_t f = 0; f < seams.foldCount(); ++f) seams.placeFoldPoints(f);
  const NearPointMerges merges =
      mergeNearPoints(lines, seams, pairsU, pairsV, pairsShared->pairs(), leaves.size());
  // Merged: the pairs and the lines' key tables are not read again (the walk finds a leaf's
  // lines by number), so they go before the runs are filled.
  LinePairs().swap(pairsU);
  LinePairs().swap(pairsV);
  pairsShared.reset();
  lines.alongU.releaseLookup();
  lines.alongV.releaseLookup();
  seams.registerPositions();

  // Leaves outside the scope are walked too, without triangles: their vertices are met in
  // the same order as in the whole mesh, so a shared vertex takes the same patch's (u, v).
  // The walk reads the line indices, merges and folds only, so runs of leaves are walked on
  // several threads (LeafRun).
  HashSet<VertexKey, VertexKeyHash> mergeTargets;
  for (const auto& [key, target] : merges.merged) mergeTargets.insert(target);
  const LeafWalkTables tables{seams, lines, merges, mergeTargets};
  parallelForChunks(leaves.size(), runLength, scope.threads, [&](size_t begin, size_t end) {
    LeafRun& run = runs[begin / runLength];
    // About a vertex and two triangles per leaf.
    run.vertices.reserve(2 * (end - begin));
    run.triangles.reserve(3 * (end - begin));
    walkLeaves(tables, leaves, begin, end, scope.firstPatch, scope.endPatch, run);
  });
}

}  // namespace

ParamMesh triangulateLeaves(const std::vector<QuadLeaf>& leaves,
                            const std::vector<BezierPatch>& patches,
                            const TriangulationScope& scope) {
  if (std::optional<ParamMesh> one = triangulateOneLeaf(leaves, patches, scope))
    return std::move(*one);
  const PatchTopology ownTopology = scope.topology ? PatchTopology{} : findSharedEdges(patches);
  const PatchTopology& topology = scope.topology ? *scope.topology : ownTopology;
  ParamMesh mesh;
  mesh.sharedEdgeGroups = topology.groupCount;
  // The mesh's arrays are sized once their sizes are known, by the numbering below, not
  // reserved by the leaves before the walk: reserved then, they sat beside the walk's tables
  // (~0.5 GiB at 10⁶ patches; bench/HISTORY.md, "The largest scene's peak memory").

  // The order counts: position ids are handed out as the folds and then the merges meet them.
  SeamVertices seams(leaves, patches, topology, scope.seamKeys);
  const size_t runLength = 512;
  thread_local KeptRuns keptRuns;
  const KeptRuns::ReleaseAtEnd releaseRuns{keptRuns};
  std::vector<LeafRun>& runs = keptRuns.take((leaves.size() + runLength - 1) / runLength);
  walkLeafRuns(leaves, topology, seams, scope, runLength, runs);

  // A key's first query in leaf order is its first query in the first run that has it: the
  // runs' vertices, run by run, meet the keys in the order one walk would. The vertices are
  // numbered in that order. Only a run's border keys (LeafRun::border) can be another run's:
  // only they are looked up, in one table on one thread (a few thousand keys), which gives
  // them their indices and tells each run how many vertices it adds; the runs then number and
  // write the rest, and their triangles, on threads.
  std::vector<size_t> borderStart(runs.size() + 1, 0);
  for (size_t r = 0; r < runs.size(); ++r)
    borderStart[r + 1] = borderStart[r] + runs[r].border.size();
  // Kept per calling thread up to a few MiB (RunPlaces::reset); a huge mesh's is freed.
  thread_local RunPlaces keptBorderFirst(0);
  RunPlaces ownBorderFirst(0);
  RunPlaces& borderFirst = borderStart.back() <= kKeptBorderKeys ? keptBorderFirst : ownBorderFirst;
  // Most border keys are met by two runs: room for half of them (the table grows past that),
  // at most half full, keeps a huge mesh's table to about its distinct keys' size.
  borderFirst.reset(borderStart.back() / 2);
  std::vector<uint32_t> borderId(borderStart.back());  // per border key, its vertex index
  std::vector<uint8_t> repeated(borderStart.back());   // ... met by an earlier run first
  std::vector<size_t> vertexStart(runs.size() + 1, 0), runStart(runs.size() + 1, 0);
  size_t triangles = 0;
  std::vector<size_t> firstTriangle(runs.size());
  for (size_t r = 0; r < runs.size(); ++r) {
    const LeafRun& run = runs[r];
    size_t repeats = 0;  // so far in the run: a vertex's index is its place less those before it
    for (size_t j = 0, b = borderStart[r]; j < run.border.size(); ++j, ++b) {
      bool added;
      const uint32_t first =
          borderFirst.findOrAdd(run.vertices[run.border[j]].key, uint32_t(b), added);
      borderId[b] = added ? uint32_t(vertexStart[r] + run.border[j] - repeats) : borderId[first];
      repeated[b] = !added;
      repeats += !added;
    }
    vertexStart[r + 1] = vertexStart[r] + run.vertices.size() - repeats;
    runStart[r + 1] = runStart[r] + run.vertices.size();
    firstTriangle[r] = triangles;
    triangles += run.triangles.size();
    mesh.droppedTriangles += run.droppedTriangles;
    mesh.diagonalFans += run.diagonalFans;
  }
  // The border keys are not looked up again: a huge mesh's own table (~0.2 GiB at 10⁶
  // patches) goes before the mesh's arrays are made.
  if (&borderFirst == &ownBorderFirst) ownBorderFirst = RunPlaces(0);
  mesh.vertices.resize(vertexStart.back());
  if (scope.seamKeys) mesh.seamKeys.resize(vertexStart.back());
  mesh.indices.resize(3 * triangles);
  mesh.cornerUv.resize(3 * triangles);
  mesh.trianglePatch.resize(triangles);
  std::vector<uint32_t> ids(runStart.back());  // per run vertex, its index
  // A run is numbered and written in ~5 µs, a worker woken in ~40: a second thread pays for
  // itself only from a few dozen runs on (a small tree's 9 are done here at once).
  const unsigned numberingThreads = runs.size() >= kRunsForSecondThread ? scope.threads : 1;
  parallelForChunks(runs.size(), 1, numberingThreads, [&](size_t begin, size_t end) {
    for (size_t r = begin; r < end; ++r) {
      const LeafRun& run = runs[r];
      uint32_t id = uint32_t(vertexStart[r]);
      size_t j = 0;  // the run's next border place
      for (size_t k = 0, q = runStart[r]; k < run.vertices.size(); ++k, ++q) {
        if (j < run.border.size() && run.border[j] == k) {
          const size_t b = borderStart[r] + j++;
          ids[q] = borderId[b];
          if (repeated[b]) continue;  // written by the run that met it first
        } else {
          ids[q] = id;
        }
        const VertexQuery& query = run.vertices[k];
        mesh.vertices[id] = {query.patch, query.uv.x, query.uv.y};
        if (scope.seamKeys) mesh.seamKeys[id] = seams.seamKeyOf(query.key);
        ++id;
      }
      size_t t = firstTriangle[r];
      for (const RunTriangle& triangle : run.triangles) {
        for (int c = 0; c < 3; ++c) {
          mesh.indices[3 * t + c] = ids[runStart[r] + triangle.vertex[c]];
          mesh.cornerUv[3 * t + c] = triangle.uv[c];
        }
        mesh.trianglePatch[t++] = triangle.patch;
      }
    }
  });
  return mesh;
}

}  // namespace tessera
