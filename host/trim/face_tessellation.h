// Step 1 of the trimmed mesher (mesher.h), for every face of a model at once: rule T's
// quad-tree of each face's Bézier pieces at δ, triangulated and evaluated. The faces' pieces go
// into one tree per patch kind (bicubic polynomial faces on the fast path, all others general:
// the kind each face would get alone), so the backend sees a few large batches instead of one
// round trip per face; then each face's leaves are triangulated on their own (the welding of
// patch sides with equal control points and of equal positions stays inside a face, so two
// faces never weld: they meet only through their shared trim points), and all vertices are
// evaluated in one call per tree. Without the trim pass each face's Tessellation is bit for
// bit what tessellate() gives for that face's pieces alone in the same frame (rule T decides a
// node from its own patch only, and the mirror evaluates each point on its own).
//
// With `trim` set, the tree is built by buildTrimmedQuadtree: nodes outside a face's loops
// stop splitting, and those leaves are left out of the triangulation (none of their triangles
// could be kept: a triangle touching a node outside the material is Outside or Crossing).
#pragma once
#include <vector>

#include "mesh/tessellate.h"
#include "trim/trim_classifier.h"
#include "trim/trimmed_face.h"

namespace tessera {

struct FaceTessellations {
  // Per face of the model: its pieces' mesh (patch k = the face's piece k), as tessellate()
  // would return it; tree holds the face's triangulated leaves only.
  std::vector<Tessellation> faces;
  size_t trees = 0;               // quad-trees built (one per patch kind present)
  size_t leaves = 0;              // all leaves, trimmed-away ones included
  size_t trimmedAwayLeaves = 0;   // leaves outside the loops, not triangulated
  double treeMs = 0, trimMs = 0;  // building the trees; of which the trim classification
  double triangulateMs = 0;       // wall time, faces in parallel
  double evaluateMs = 0;          // the backend's vertex evaluation
  double assembleMs = 0;          // welding and per-face meshes, faces in parallel
};

// `trim` may be null (no trim pass). `threads` as parallelFor takes it (0: all cores). The
// trees work in `frame` (δ/scale there) and the faces' meshes come back in model coordinates
// (tessellate.h, toModelCoordinates); a face's mesh is what tessellate() gives its pieces
// alone in that frame.
FaceTessellations tessellateFaces(const TrimmedModel& model, double tolerance,
                                  const ModelFrame& frame, Backend& backend, TrimClassifier* trim,
                                  unsigned threads);

// The frame of every face's pieces together (modelFrame): one per model, so that a model's
// faces are meshed alike wherever the model sits.
ModelFrame trimmedModelFrame(const TrimmedModel& model);

}  // namespace tessera
