#include "trim/face_tessellation.h"

#include <algorithm>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>

#include "common/parallel_for.h"
#include "common/stopwatch.h"
#include "geometry/general_patch.h"
#include "mesh/triangulate.h"
#include "trim/revolution_bound.h"
#include "trim/trim_frontier.h"

namespace tessera {
namespace {

// The faces of one tree, their pieces one after another in face order.
struct FaceGroup {
  std::vector<size_t> faces;                          // indices into model.faces
  std::vector<std::vector<BezierPatch>> facePatches;  // per face of the group
  std::vector<uint32_t> firstPatch;                   // per face, its first patch in the tree
  std::vector<BezierPatch> patches;                   // all, in tree order, in the local frame
};

bool isBicubicFace(const TrimmedFace& face) {
  return std::all_of(face.pieces.begin(), face.pieces.end(),
                     [](const BezierPatchPiece& p) { return isBicubicPolynomial(p.patch); });
}

// The group's loops and piece rectangles, face k of the group being trim face k.
TrimSet groupTrimSet(const TrimmedModel& model, const FaceGroup& group) {
  std::vector<std::vector<std::vector<glm::dvec2>>> loops(group.faces.size());
  std::vector<TrimPieceRect> pieces;
  for (size_t k = 0; k < group.faces.size(); ++k) {
    const TrimmedFace& face = model.faces[group.faces[k]];
    for (const TrimLoop& loop : face.loops) loops[k].push_back(loop.uv);
    for (const BezierPatchPiece& p : face.pieces)
      pieces.push_back({uint32_t(k), {p.u0, p.v0, p.u1, p.v1}});
  }
  return packTrimSet(loops, pieces);
}

// Faces a thread takes at a time in tessellateFaces' checks: a face is a few pieces.
constexpr size_t kFacesPerTurn = 16;

// Face f's pieces, each checked by validateTessellationPatch, in the tree's local frame.
std::vector<BezierPatch> localFacePatches(const TrimmedFace& face, size_t f,
                                          const ModelFrame& frame) {
  std::vector<BezierPatch> patches;
  patches.reserve(face.pieces.size());
  for (size_t k = 0; k < face.pieces.size(); ++k) {
    // The piece's name only for the message (validateTessellationPatch's is its `what`, a
    // space and the reason): building it for every piece was most of this loop.
    try {
      validateTessellationPatch(face.pieces[k].patch, std::string());
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument((face.label.empty() ? "face " + std::to_string(f) : face.label) +
                                  ", piece " + std::to_string(k) + e.what());
    }
    patches.push_back(face.pieces[k].patch);
  }
  return toLocalFrame(std::move(patches), frame);
}

void tessellateGroup(const TrimmedModel& model, const FaceGroup& group, const ModelFrame& frame,
                     const QuadtreeOptions& options, Backend& backend, TrimClassifier* trim,
                     unsigned threads, FaceTessellations& out) {
  Stopwatch step;
  const PatchSet patchSet = toPatchSet(group.patches);
  backend.evaluator->prepareVertices(patchSet);  // overlaps the tree on backends that can
  // Faces known as surfaces of revolution are decided by their distance bound
  // (revolution_bound.h), the others by rule T's parametric one.
  std::vector<std::unique_ptr<FaceSurface>> surfaces(group.faces.size());
  std::vector<RevolutionBoundClassifier::Patch> revolutionPatches;
  for (size_t k = 0; k < group.faces.size(); ++k) {
    const TrimmedFace& face = model.faces[group.faces[k]];
    const bool known = face.revolution.profile != RevolutionForm::Profile::None;
    if (known) surfaces[k] = std::make_unique<FaceSurface>(face);
    for (size_t piece = 0; piece < face.pieces.size(); ++piece)
      revolutionPatches.push_back({known ? &face.revolution : nullptr, surfaces[k].get(), piece});
  }
  RevolutionBoundClassifier revolution(*backend.classifier, std::move(revolutionPatches),
                                       frame.scale, threads);
  QuadtreeResult tree;
  if (trim) {
    const TrimSet set = groupTrimSet(model, group);
    TrimmingClassifier trimming(revolution, set, *trim);
    tree = buildQuadtree(patchSet, options, trimming);
    out.trimMs += trimming.trimMs();
  } else {
    tree = buildQuadtree(patchSet, options, revolution);
  }
  ++out.trees;
  out.leaves += tree.leaves.size();

  // Each face's leaves, in tree order, renumbered to the face's own pieces.
  const size_t faceCount = group.faces.size();
  std::vector<QuadtreeResult> faceTrees(faceCount);
  for (const QuadLeaf& leaf : tree.leaves) {
    if (trim && leaf.cause == gpu::kCauseTrimmedAway) {
      ++out.trimmedAwayLeaves;
      continue;
    }
    const size_t k = size_t(std::upper_bound(group.firstPatch.begin(), group.firstPatch.end(),
                                             leaf.patchIndex) -
                            group.firstPatch.begin()) -
                     1;
    QuadLeaf local = leaf;
    local.patchIndex -= group.firstPatch[k];
    faceTrees[k].depth = std::max(faceTrees[k].depth, leaf.level);
    faceTrees[k].boundScale = frame.scale;
    faceTrees[k].leaves.push_back(local);
  }
  out.treeMs += step.elapsedMs();

  step.restart();
  // Faces of very different sizes: a face at a time, the most leaves first (parallel_for.h).
  std::vector<double> leafCounts(faceCount);
  for (size_t k = 0; k < faceCount; ++k) leafCounts[k] = double(faceTrees[k].leaves.size());
  std::vector<ParamMesh> params(faceCount);
  parallelForLargestFirst(leafCounts, threads, [&](size_t k) {
    if (!faceTrees[k].leaves.empty())
      params[k] = triangulateLeaves(faceTrees[k].leaves, group.facePatches[k]);
  });
  out.triangulateMs += step.elapsedMs();

  // Every face's vertices in one backend call: the round trip is paid once per tree.
  step.restart();
  std::vector<size_t> firstQuery(faceCount + 1, 0);
  for (size_t k = 0; k < faceCount; ++k) firstQuery[k + 1] = firstQuery[k] + params[k].vertices.size();
  std::vector<gpu::EvalQuery> queries(firstQuery.back());
  for (size_t k = 0; k < faceCount; ++k)
    for (size_t i = 0; i < params[k].vertices.size(); ++i) {
      const ParamVertex& v = params[k].vertices[i];
      queries[firstQuery[k] + i] = {v.patchIndex + group.firstPatch[k], v.u, v.v, 0};
    }
  // The faces are assembled from the samples where the evaluator holds them (Vulkan: its
  // mapped buffer), so no copy of them is made.
  const auto assembleFaces = [&](const gpu::VertexSample* samples) {
    out.evaluateMs += step.elapsedMs();
    step.restart();
    parallelForLargestFirst(leafCounts, threads, [&](size_t k) {
      Tessellation& face = out.faces[group.faces[k]];
      face = assembleTessellation(group.facePatches[k].size(), std::move(faceTrees[k]),
                                  std::move(params[k]), samples + firstQuery[k]);
      toModelCoordinates(face, frame);
    });
  };
  backend.evaluator->useVertexSamples(patchSet, std::move(queries), assembleFaces);
  out.assembleMs += step.elapsedMs();
}

}  // namespace

FaceTessellations tessellateFaces(const TrimmedModel& model, double tolerance,
                                  const ModelFrame& frame, Backend& backend, TrimClassifier* trim,
                                  unsigned threads) {
  FaceTessellations out;
  out.faces.resize(model.faces.size());
  FaceGroup groups[2];  // bicubic polynomial faces, the others
  // Each face's pieces checked and moved to the local frame on all threads (on one, this was
  // 6–13% of the CPU tree's time on the IDF library); the lowest face's error is thrown, as a
  // loop in order would.
  const size_t faceCount = model.faces.size();
  std::vector<std::vector<BezierPatch>> localPatches(faceCount);
  std::vector<std::exception_ptr> errors(faceCount);
  parallelForChunks(faceCount, kFacesPerTurn, threadsForChunks(faceCount, kFacesPerTurn, threads),
                    [&](size_t begin, size_t end) {
                      for (size_t f = begin; f < end; ++f) {
                        try {
                          localPatches[f] = localFacePatches(model.faces[f], f, frame);
                        } catch (...) {
                          errors[f] = std::current_exception();
                        }
                      }
                    });
  for (const std::exception_ptr& error : errors)
    if (error) std::rethrow_exception(error);
  for (size_t f = 0; f < faceCount; ++f) {
    const TrimmedFace& face = model.faces[f];
    FaceGroup& group = groups[isBicubicFace(face) ? 0 : 1];
    std::vector<BezierPatch>& patches = localPatches[f];
    group.faces.push_back(f);
    group.firstPatch.push_back(uint32_t(group.patches.size()));
    group.patches.insert(group.patches.end(), patches.begin(), patches.end());
    group.facePatches.push_back(std::move(patches));
  }
  const QuadtreeOptions options = toleranceOptions(tolerance / frame.scale);
  for (const FaceGroup& group : groups)
    if (!group.faces.empty())
      tessellateGroup(model, group, frame, options, backend, trim, threads, out);
  return out;
}

ModelFrame trimmedModelFrame(const TrimmedModel& model) {
  ControlPointBox box;
  for (const TrimmedFace& face : model.faces)
    for (const BezierPatchPiece& piece : face.pieces) extendBox(box, piece.patch);
  return modelFrame(box);
}

}  // namespace tessera
