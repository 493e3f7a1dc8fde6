// The trimmed mesher (issue 17): a TrimmedModel → one indexed mesh, watertight across faces.
// Rule T's quad-trees of all faces' pieces at δ, built together on the backend with the trim
// pass (face_tessellation.h); then per face, faces in parallel: its triangles classified
// against the trimming loops (trim_cut.h): inside kept, outside dropped, crossing dropped; the
// gap between the kept triangles and the loops triangulated with the loops' own points and no
// other point on them (gap_triangulate.h); gap triangles measured and split until within δ.
// Every trim point becomes the one vertex of its shared point id, at
// TrimmedModel::sharedPoints[id], so two faces that share an edge share its vertices and its
// segments, and a closed solid gives a closed mesh. Design and bounds: docs/trimmed_faces.md.
#pragma once
#include <cstdint>
#include <optional>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "mesh/mesh.h"
#include "mesh/tessellate.h"
#include "trim/trim_classifier.h"
#include "trim/trimmed_face.h"

namespace tessera {

// How a gap triangle is judged against δ (docs/trimmed_faces.md, "Refine"). Geometric: the
// distance of its sample points to the surface (closestPointOnPatch from the sample's (u, v),
// an upper bound), what CAD users and bench_cad measure. Parametric: the distance to the surface
// point at the same (u, v) mix, as rule T bounds the kept triangles: stronger, but on rational
// surfaces (an exact circle is not parametrised by angle) it counts sliding along the surface.
enum class GapMeasure { Geometric, Parametric };

struct TrimmedMeshOptions {
  double tolerance = 0;            // δ, model units, > 0
  int deviationSubdivisions = 8;   // samples (i, j, k)/n of each triangle: refinement and stats
  bool measureGeometric = true;    // also the distance to the surface (slower)
  // The stats measure every emitted triangle; off, only the gap triangles (the kept quad-tree
  // triangles are proven within δ by rule T, so measuring them only confirms the proof; it is
  // most of the stats' cost). The gap refinement measures gap triangles either way.
  bool measureKeptTriangles = true;
  // Build the faces' quad-trees with the trim pass (trim_frontier.h): nodes outside a face's
  // loops stop splitting and are not triangulated. Off: the untrimmed trees.
  bool trimQuadtree = true;
  int maxRefineRounds = 24;        // splitting rounds for gap triangles over δ
  GapMeasure gapMeasure = GapMeasure::Geometric;
  // Faces whose surface is affine (planes) skip the gap refinement's sampling, which cannot
  // split there, and take the gap metric from their sides instead of meanScales
  // (detail/affine_face.h): the same mesh; their gap triangles' parametric deviation is their
  // corners' offsets, without the samples' rounding. Off: sampled as before, for tests.
  bool affineShortcut = true;
  unsigned threads = 0;            // faces cut in parallel (0: all cores); output independent
  // The local frame of the quad-trees (geometry/model_frame.h); unset: the model's own
  // (trimmedModelFrame). A face meshed alone in its model's frame meshes as in the model.
  std::optional<ModelFrame> frame;
};

struct TrimmedFaceStats {
  uint32_t faceIndex = 0;            // TrimmedFace::faceIndex
  size_t quadtreeTriangles = 0;      // rule T's triangles of the face's pieces
  size_t keptTriangles = 0;          // of those, wholly inside the trim (split halves count)
  size_t gapTriangles = 0;           // triangles between the kept ones and the loops
  size_t triangles = 0;              // emitted (kept + gap − collapsed)
  size_t refinementSplits = 0;       // edges or triangles split for the gap to meet δ
  // Gap triangles still over δ when the refinement's rounds ran out (maxRefineRounds): 0 unless
  // the face breaks its promise; the CLI warns naming the face.
  size_t unfinishedGapTriangles = 0;
  size_t collapsedTriangles = 0;     // two corners on one shared point (a pole, a seam end)
  // gap_triangulate.h's failures: 0 unless the loops are bad (open, crossing each other or
  // themselves); then the face's mesh may have holes or overlaps, and a caller should report
  // the face (its label) rather than write it silently.
  size_t gapFailures = 0;
  // Measured over every emitted triangle at deviationSubdivisions: parametric (the triangle
  // point against the surface at the same uv mix) and geometric (distance to the surface).
  double maxParametricDeviation = 0, maxGeometricDeviation = 0;
  double maxGapParametricDeviation = 0;  // over the gap triangles alone
  // The largest distance of a trim point (a shared B-rep edge point) from this face's surface:
  // the file's edge gap where its 3D curves and pcurves disagree (CadEdgeWarning), rounding
  // otherwise. Refinement measures triangles with their corners on the surface, so it cannot
  // reduce this: the promise is deviation ≤ δ + maxTrimPointOffset (docs/trimmed_faces.md).
  double maxTrimPointOffset = 0;
  // Emitted triangles the maxima above were taken over: all of them, or only the gap ones
  // when TrimmedMeshOptions::measureKeptTriangles is off.
  size_t measuredTriangles = 0;
};

// Where the time went (wall milliseconds; per-face stages run faces in parallel).
struct TrimmedMeshTimings {
  double treeMs = 0;         // quad-trees of all faces (face_tessellation.h), trim pass included
  double trimMs = 0;         // of which the trim classification of nodes
  double triangulateMs = 0;  // leaves → triangles, per face
  double evaluateMs = 0;     // the backend's vertex evaluation, one call per tree
  double assembleMs = 0;     // per-face meshes (welding)
  double cutMs = 0;          // classify, gap, refine and measure, per face
  // cutMs's parts, thread time summed over the faces (so they may add up to more than cutMs)
  double classifyCpuMs = 0, gapCpuMs = 0, refineCpuMs = 0, measureCpuMs = 0;
  double emitMs = 0;         // shared vertices and the one mesh, in face order
  double totalMs = 0;
  size_t trees = 0, leaves = 0, trimmedAwayLeaves = 0;
};

struct TrimmedMesh {
  TriangleMesh mesh;  // positions, uvs and patchIds (= face position in the model) per vertex;
                      // a shared point's vertex carries the uv of the first face using it
  std::vector<uint32_t> triangleFace;  // per triangle: index into TrimmedModel::faces
  std::vector<glm::dvec2> cornerUv;    // 3 per triangle: the corners' uv on that face
  std::vector<TrimmedFaceStats> faces;
  TrimmedMeshTimings timings;
};

// Throws std::invalid_argument naming the face (its label) and loop for a model it cannot
// mesh: no pieces, a piece with an empty or non-finite rectangle, a loop under 3 points,
// pointIds not one per uv, an id past sharedPoints, a non-finite uv.
void validateTrimmedModel(const TrimmedModel& model);

// All faces' quad-trees are built together on `backend` (face_tessellation.h), then each face
// is cut on the CPU, faces in parallel, and emitted in face order. `trim` classifies the
// quad-tree nodes against the loops when options.trimQuadtree is on; null: the fp32 mirror.
// Pass makeVulkanTrimClassifier with a Vulkan backend to keep the tree on the device.
TrimmedMesh meshTrimmedModel(const TrimmedModel& model, const TrimmedMeshOptions& options,
                             Backend& backend, TrimClassifier* trim = nullptr);

// One message per face whose gap refinement ran out of rounds over δ
// (TrimmedFaceStats::unfinishedGapTriangles), naming the face, the triangles left, the largest
// measured distance (said within δ or over it) and the trim points' own offset from the surface
// where the file's edges leave it: what a caller reports rather than pass the face off as
// within δ.
std::vector<std::string> unfinishedRefinementWarnings(const TrimmedMesh& mesh, double tolerance);

}  // namespace tessera
