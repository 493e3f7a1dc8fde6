#include "mesh/tessellate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "common/stopwatch.h"
#include "mesh/mesh_cleanup.h"
#include "mesh/triangulate.h"
#include "mesh/zero_area.h"

namespace tessera {
namespace {

// Removes the triangles `dropped` (ascending) from the mesh and its per-triangle records,
// counting them as degenerate.
void dropTriangles(const std::vector<uint32_t>& dropped, Tessellation& result) {
  if (dropped.empty()) return;
  // The triangles before the first dropped one stay where they are.
  std::vector<uint32_t>& indices = result.mesh.indices;
  const size_t count = result.trianglePatch.size();
  size_t kept = dropped[0], next = 0;
  for (size_t t = dropped[0]; t < count; ++t) {
    if (next < dropped.size() && dropped[next] == t) {
      ++next;
      ++result.stats.degenerateTrianglesDropped;
      continue;
    }
    for (size_t c = 0; c < 3; ++c) {
      indices[3 * kept + c] = indices[3 * t + c];
      result.cornerUv[3 * kept + c] = result.cornerUv[3 * t + c];
    }
    result.trianglePatch[kept++] = result.trianglePatch[t];
  }
  indices.resize(3 * kept);
  result.cornerUv.resize(3 * kept);
  result.trianglePatch.resize(kept);
}

}  // namespace

Backend makeMirrorBackend() {
  return {"cpu", makeParallelMirrorClassifier(), makeMirrorEvaluator()};
}

namespace {

// meshFromTree frees a patch set it owns that is larger than this during the triangulation.
constexpr size_t kRemadePatchSetBytes = size_t(64) << 20;

ParamMesh triangulateOnAllCores(const std::vector<QuadLeaf>& leaves,
                                const std::vector<BezierPatch>& patches) {
  TriangulationScope onAllCores;
  onAllCores.threads = 0;
  return triangulateLeaves(leaves, patches, onAllCores);
}

// The rest of meshFromTree once the leaves are triangulated (in `triangulateMs`; `total` runs
// from the start). The queries go as soon as they are evaluated: a huge mesh's are ~64 MiB
// (bench/HISTORY.md, "The largest scene's peak memory").
Tessellation meshFromTriangulation(size_t patchCount, QuadtreeResult tree, ParamMesh param,
                                   PatchEvaluator& evaluator, const PatchSet& gpuPatches,
                                   const ModelFrame& frame, double triangulateMs,
                                   const Stopwatch& total) {
  const Stopwatch step;
  std::vector<gpu::EvalQuery> queries(param.vertices.size());
  for (size_t i = 0; i < queries.size(); ++i)
    queries[i] = {param.vertices[i].patchIndex, param.vertices[i].u, param.vertices[i].v, 0};
  double evaluateMs = 0;
  Tessellation result;
  // The mesh is assembled from the samples where the evaluator holds them (no copy of them).
  evaluator.useVertexSamples(gpuPatches, std::move(queries), [&](const gpu::VertexSample* samples) {
    evaluateMs = step.elapsedMs();
    result = assembleTessellation(patchCount, std::move(tree), std::move(param), samples, 0);
  });
  toModelCoordinates(result, frame);
  result.stats.triangulateMs = triangulateMs;
  result.stats.evaluateMs = evaluateMs;
  result.stats.totalMs = total.elapsedMs();
  return result;
}

}  // namespace

Tessellation assembleTessellation(size_t patchCount, QuadtreeResult tree, ParamMesh param,
                                  const std::vector<gpu::VertexSample>& samples, unsigned threads) {
  if (samples.size() != param.vertices.size())
    throw std::invalid_argument("assembleTessellation: " + std::to_string(samples.size()) +
                                " samples for " + std::to_string(param.vertices.size()) +
                                " vertices");
  return assembleTessellation(patchCount, std::move(tree), std::move(param), samples.data(),
                              threads);
}

Tessellation assembleTessellation(size_t patchCount, QuadtreeResult tree, ParamMesh param,
                                  const gpu::VertexSample* samples, unsigned threads) {
  const size_t count = param.vertices.size();
  Tessellation result;
  result.tree = std::move(tree);
  TriangleMesh& mesh = result.mesh;
  mesh.positions.resize(count);
  mesh.normals.resize(count);
  mesh.uvs.resize(count);
  mesh.patchIds.resize(count);
  // The samples are checked finite in the same pass as they are copied (one read of them);
  // requireFiniteSamples names the first that is not.
  bool finite = true;
  for (size_t i = 0; i < count; ++i) {
    const glm::vec3 position(samples[i].position), normal(samples[i].normal);
    finite &= std::isfinite(position.x) & std::isfinite(position.y) & std::isfinite(position.z) &
              std::isfinite(normal.x) & std::isfinite(normal.y) & std::isfinite(normal.z);
    mesh.positions[i] = position;
    mesh.normals[i] = normal;
    mesh.uvs[i] = glm::vec2(param.vertices[i].u, param.vertices[i].v);
    mesh.patchIds[i] = param.vertices[i].patchIndex;
  }
  if (!finite) requireFiniteSamples(param, samples, count);
  // Welding in the triangulation already dropped triangles with two corners at one vertex.
  // Distinct vertices can still evaluate to the very same point (a fold, or points a hair
  // apart): weld those too, so a triangle with two corners there goes and its neighbours keep
  // sharing their edges; then back-to-back pairs cancel and caps (three corners on one line)
  // are flipped away (zero_area.h).
  std::vector<uint32_t> remap = weldIdenticalPositions(mesh.positions, threads);
  result.stats.degenerateTrianglesDropped = param.droppedTriangles;
  result.stats.diagonalFans = param.diagonalFans;
  mesh.indices = std::move(param.indices);
  result.trianglePatch = std::move(param.trianglePatch);
  result.cornerUv = std::move(param.cornerUv);
  std::vector<uint32_t> collapsed;
  for (size_t t = 0; t < result.trianglePatch.size(); ++t) {
    uint32_t* c = &mesh.indices[3 * t];
    c[0] = remap[c[0]], c[1] = remap[c[1]], c[2] = remap[c[2]];
    if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0]) collapsed.push_back(uint32_t(t));
  }
  dropTriangles(collapsed, result);
  dropTriangles(backToBackTriangles(mesh.indices, threads), result);
  dropTriangles(removeCapTriangles(mesh.positions, mesh.indices, result.trianglePatch,
                                   result.cornerUv, threads),
                result);

  TessellationStats& s = result.stats;
  s.patches = patchCount;
  s.leaves = result.tree.leaves.size();
  s.depth = result.tree.depth;
  s.levels = result.tree.levels;
  s.triangles = mesh.triangleCount();
  s.vertices = mesh.vertexCount();
  return result;
}

Tessellation tessellate(const std::vector<BezierPatch>& patches, const QuadtreeOptions& options,
                        Backend& backend) {
  const Stopwatch total;
  for (size_t i = 0; i < patches.size(); ++i)
    validateTessellationPatch(patches[i], "patch " + std::to_string(i));
  // Everything below sees the model in its local frame: coordinates in [−1, 1], δ in its units.
  const ModelFrame frame = modelFrame(patches);
  std::vector<BezierPatch> local = toLocalFrame(patches, frame);
  QuadtreeOptions localOptions = options;
  if (options.rule == SplitRule::Tolerance)
    localOptions.tolerance = options.tolerance / frame.scale;
  // Bicubic polynomial patches take the BicubicPatch shaders; anything else sends the whole
  // set through the general ones (a bicubic patch is a general patch too): toPatchSet.
  const Stopwatch treeStep;
  PatchSet gpuPatches = toPatchSet(local);
  // The evaluator's setup (a pipeline build) overlaps the quad-tree from its first level on:
  // started before it, it would take cores from the classifier's own pipeline builds, which
  // the first level waits for (lavapipe builds on the calling threads;
  // bench/HISTORY.md, "The Vulkan path's fixed cost").
  bool evaluatorPrepared = false;
  localOptions.onLevel = [&, outer = options.onLevel](const LevelStats& level) {
    if (!evaluatorPrepared) backend.evaluator->prepareVertices(gpuPatches);
    evaluatorPrepared = true;
    if (outer) outer(level);
  };
  QuadtreeResult tree = buildQuadtree(gpuPatches, localOptions, *backend.classifier);
  tree.boundScale = frame.scale;
  const double treeMs = treeStep.elapsedMs();
  Tessellation result = meshFromTree(std::move(local), std::move(gpuPatches), std::move(tree),
                                     *backend.evaluator, frame);
  result.stats.treeMs = treeMs;
  result.stats.totalMs = total.elapsedMs();
  return result;
}

Tessellation meshFromTree(const std::vector<BezierPatch>& patches, const PatchSet& gpuPatches,
                          QuadtreeResult tree, PatchEvaluator& evaluator, const ModelFrame& frame) {
  const Stopwatch total;
  ParamMesh param = triangulateOnAllCores(tree.leaves, patches);
  return meshFromTriangulation(patches.size(), std::move(tree), std::move(param), evaluator,
                               gpuPatches, frame, total.elapsedMs(), total);
}

Tessellation meshFromTree(std::vector<BezierPatch>&& patches, PatchSet&& gpuPatches,
                          QuadtreeResult tree, PatchEvaluator& evaluator, const ModelFrame& frame) {
  // Each copy of the patches alive only while read (bench/HISTORY.md, "The largest scene's peak
  // memory"): the triangulation reads `patches` only, the evaluation `gpuPatches` only. A set
  // over kRemadePatchSetBytes (0.25 GiB at 10⁶ bicubic patches) is freed for the
  // triangulation, whose tables are the run's peak, and made again from `patches` (the same
  // bytes); a smaller one is kept, remaking it would only cost time. `patches` go once
  // triangulated (0.44 GiB there).
  const Stopwatch total;
  const size_t patchCount = patches.size();
  const bool remade = gpuPatches.bufferBytes(0, gpuPatches.size()) > kRemadePatchSetBytes;
  if (remade) gpuPatches = PatchSet();
  ParamMesh param = triangulateOnAllCores(tree.leaves, patches);
  const double triangulateMs = total.elapsedMs();
  if (remade) gpuPatches = toPatchSet(patches);
  std::vector<BezierPatch>().swap(patches);
  return meshFromTriangulation(patchCount, std::move(tree), std::move(param), evaluator, gpuPatches,
                               frame, triangulateMs, total);
}

void toModelCoordinates(Tessellation& t, const ModelFrame& frame) {
  t.frame = frame;
  for (glm::vec3& p : t.mesh.positions) p = glm::vec3(frame.toModel(glm::dvec3(p)));
}

}  // namespace tessera
