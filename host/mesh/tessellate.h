// The whole job: patches → adaptive quad-tree → triangles → vertices evaluated on the
// backend → an indexed mesh with positions, normals, (u, v) and patch ids.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "eval/evaluator.h"
#include "eval/patch_set.h"
#include "geometry/model_frame.h"
#include "geometry/patch.h"
#include "mesh/mesh.h"
#include "quadtree/quadtree.h"

namespace tessera {

struct ParamMesh;

// A classifier and an evaluator on the same device.
struct Backend {
  std::string name;
  std::unique_ptr<NodeClassifier> classifier;
  std::unique_ptr<PatchEvaluator> evaluator;
};

Backend makeMirrorBackend();  // fp32 mirror, all cores for the tree and large evaluations
// The tree's rule T batches of fewer than `hostLevelNodes` nodes are decided on the host by
// the fp32 mirror (withSmallLevelsOnHost; 0: every batch on the device, for parity tests).
Backend makeVulkanBackend(vk::Context& context, size_t hostLevelNodes = kHostLevelNodes);

struct TessellationStats {
  size_t patches = 0, leaves = 0, triangles = 0, vertices = 0;
  size_t degenerateTrianglesDropped = 0;  // zero-area triangles at collapsed edges,
                                          // back-to-back pairs and caps (docs/watertight.md)
  size_t diagonalFans = 0;  // rule-T leaves proven for one diagonal that kept a fan (their
                            // bound is then only the any-triangle one: ParamMesh::diagonalFans)
  uint32_t depth = 0;
  double treeMs = 0, triangulateMs = 0, evaluateMs = 0, totalMs = 0;
  std::vector<LevelStats> levels;
};

struct Tessellation {
  TriangleMesh mesh;
  // Per triangle of `mesh`: its patch and its corners' (u, v) on that patch (a welded vertex's
  // own uv is from one of the patches that share it). What measureDeviation needs.
  std::vector<uint32_t> trianglePatch;
  std::vector<glm::vec2> cornerUv;
  QuadtreeResult tree;
  TessellationStats stats;
  // The local frame the tree, the evaluation and the welding worked in (model_frame.h);
  // mesh.positions are in model coordinates, each mapped back in double and rounded once.
  ModelFrame frame;
};

// Takes patches of degree 1..7 each way, polynomial or rational (weights ≥ 0, corner weights
// > 0): all bicubic polynomial → the BicubicPatch shaders, else the general ones for all.
// Works in the patches' local frame (modelFrame; rule T's δ becomes δ/scale there), so the
// tree does not depend on where the model sits or on its units. Throws std::invalid_argument
// naming the patch for one it cannot take (validateTessellationPatch) or one whose fp32
// evaluation is not finite, TessellationLimitError when the node budget is exceeded.
Tessellation tessellate(const std::vector<BezierPatch>& patches, const QuadtreeOptions& options,
                        Backend& backend);

// The second half of tessellate(): a finished tree → watertight mesh, vertices evaluated by
// `evaluator` (useVertexSamples; timings in stats.triangulateMs and stats.evaluateMs). `patches`
// and `gpuPatches` are in `frame` (toLocalFrame); the mesh comes back in model coordinates
// (toModelCoordinates).
Tessellation meshFromTree(const std::vector<BezierPatch>& patches, const PatchSet& gpuPatches,
                          QuadtreeResult tree, PatchEvaluator& evaluator,
                          const ModelFrame& frame = {});

// The same for a caller done with its patches, `gpuPatches` = toPatchSet(patches): each copy is
// freed once no step reads it, and a huge patch set is made again for the evaluation rather
// than held through the triangulation (the mesh is the same bytes; docs/hardening.md).
Tessellation meshFromTree(std::vector<BezierPatch>&& patches, PatchSet&& gpuPatches,
                          QuadtreeResult tree, PatchEvaluator& evaluator,
                          const ModelFrame& frame = {});

// meshFromTree's last step, for callers that triangulate and evaluate themselves (the trimmed
// mesher evaluates many trees' vertices in one backend call): `samples` are the evaluations of
// param.vertices in order; welds equal positions and drops degenerate and back-to-back
// triangles as tessellate() does, all in the frame the samples are in. Timings are left at 0.
// Throws std::invalid_argument naming the patch and (u, v) of a sample that is not finite.
// The triangles' arrays are taken over from `param` (move it in where it is not needed after).
// Welding looks positions up on `threads` threads (0: all); the mesh is the same.
Tessellation assembleTessellation(size_t patchCount, QuadtreeResult tree, ParamMesh param,
                                  const std::vector<gpu::VertexSample>& samples,
                                  unsigned threads = 1);
// The same with param.vertices.size() samples at `samples`: a part of a larger batch, read in
// place (the trimmed mesher's faces share one evaluation).
Tessellation assembleTessellation(size_t patchCount, QuadtreeResult tree, ParamMesh param,
                                  const gpu::VertexSample* samples, unsigned threads = 1);

// Hands a tessellation made in `frame` out in model coordinates: each position mapped back in
// double (frame.toModel) and rounded to fp32 once; normals and (u, v) are unchanged (the frame
// is a translation and a positive uniform scale). Sets t.frame.
void toModelCoordinates(Tessellation& t, const ModelFrame& frame);

}  // namespace tessera
