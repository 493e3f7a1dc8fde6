// The trimmed mesher (issue 17): a TrimmedModel → one indexed mesh, watertight across faces.
// Per face: rule T's quad-tree tessellation of its pieces at δ (tessellate()); its triangles
// classified against the trimming loops (trim_cut.h): inside kept, outside dropped, crossing
// dropped; the gap between the kept triangles and the loops triangulated with the loops' own
// points and no other point on them (gap_triangulate.h); gap triangles measured and split
// until within δ. Every trim point becomes the one vertex of its shared point id, at
// TrimmedModel::sharedPoints[id], so two faces that share an edge share its vertices and its
// segments, and a closed solid gives a closed mesh. Design and bounds: docs/trimmed_faces.md.
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "mesh/mesh.h"
#include "mesh/tessellate.h"
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
  int maxRefineRounds = 24;        // splitting rounds for gap triangles over δ
  GapMeasure gapMeasure = GapMeasure::Geometric;
};

struct TrimmedFaceStats {
  uint32_t faceIndex = 0;            // TrimmedFace::faceIndex
  size_t quadtreeTriangles = 0;      // rule T's triangles of the face's pieces
  size_t keptTriangles = 0;          // of those, wholly inside the trim (split halves count)
  size_t gapTriangles = 0;           // triangles between the kept ones and the loops
  size_t triangles = 0;              // emitted (kept + gap − collapsed)
  size_t refinementSplits = 0;       // edges or triangles split for the gap to meet δ
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
};

struct TrimmedMesh {
  TriangleMesh mesh;  // positions, uvs and patchIds (= face position in the model) per vertex;
                      // a shared point's vertex carries the uv of the first face using it
  std::vector<uint32_t> triangleFace;  // per triangle: index into TrimmedModel::faces
  std::vector<glm::dvec2> cornerUv;    // 3 per triangle: the corners' uv on that face
  std::vector<TrimmedFaceStats> faces;
};

// Throws std::invalid_argument naming the face (its label) and loop for a model it cannot
// mesh: no pieces, a piece with an empty or non-finite rectangle, a loop under 3 points,
// pointIds not one per uv, an id past sharedPoints, a non-finite uv.
void validateTrimmedModel(const TrimmedModel& model);

TrimmedMesh meshTrimmedModel(const TrimmedModel& model, const TrimmedMeshOptions& options,
                             Backend& backend);

}  // namespace tessera
