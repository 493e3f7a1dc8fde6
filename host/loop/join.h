// Joining two Loop subdivision surfaces by local refinement (Yamada, Chiyokura, Kanai; the
// paper's §3): two closed control meshes placed so that they intersect in one region become one
// closed, consistently oriented control mesh. Steps: interfering triangles by BVH; local Loop
// refinement of them with T-node splits (loop_local_refine.h), `levels` times per side; removal
// of each side's triangles that cross or lie inside the other; a strip bridging the two boundary
// loops (loop_bridge.h); Suzuki fitting of the changed vertices and their neighbours back to
// their own original limit surfaces. Vertices away from the seam keep their positions bit for
// bit. "Paste" cuts a part off one mesh first (cutByPlane, cutByVertices) and joins it.
#pragma once
#include <cstdint>
#include <vector>

#include "loop/fit.h"
#include "loop/shapes.h"

namespace tessera {

// The most local refinement levels per side: each level splits the seam's triangles 1 → 4,
// so the seam's triangle count grows about 2× a level (the seam is a curve) and its
// triangles shrink 4× in area; past 6 the seam is far finer than any input's triangles and
// the BVH/fit work grows without helping (measured in docs/loop.md).
constexpr int kMaxLoopJoinLevels = 6;

struct LoopJoinOptions {
  // Local refinement levels of each side; −1: chosen so that the two sides' interfering
  // triangles get similar areas (the larger side gets round(log4 ratio) more levels, each at
  // least 1). Each in −1..kMaxLoopJoinLevels (else std::invalid_argument); 0 joins the
  // unrefined meshes.
  int levelsA = -1, levelsB = -1;
  int fitIterations = 50;
  int limitSurfaceLevels = 3;  // density of the original limit surfaces the fit goes back to
};

struct LoopJoinReport {
  int levelsA = 0, levelsB = 0;
  size_t trianglesIn = 0, trianglesOut = 0;   // A + B, and the joined mesh
  size_t interferingA = 0, interferingB = 0;  // triangles of the input meshes that intersect
  size_t removedA = 0, removedB = 0, bridgeTriangles = 0;
  size_t fittedVertices = 0, unchangedVertices = 0;
  double fitEnergyBefore = 0, fitEnergyAfter = 0;
  double maxDeviation = 0;  // max over fitted vertices of |p∞ − original surface|
};

struct LoopJoinResult {
  LoopShape mesh;
  // For each vertex of `mesh`: its index in A (side 0) or B (side 1), or kLoopNone for a
  // vertex made by the refinement; and whether the fit moved it.
  std::vector<uint32_t> source;
  std::vector<uint8_t> side, fitted;
  LoopJoinReport report;
};

// Throws std::invalid_argument (bad input geometry) when the meshes do not intersect, or their
// intersection does not leave exactly one boundary loop on each side.
LoopJoinResult joinLoopMeshes(const LoopShape& a, const LoopShape& b,
                              const LoopJoinOptions& options = {});

// The part of a closed mesh on the positive side of the plane dot(n, x) = d, as an open mesh
// (faces with every corner on that side; the largest piece). For "paste": the cut part is
// closed by joining it into another mesh, so its open rim must lie inside the other mesh.
LoopShape cutByPlane(const LoopShape& mesh, const glm::dvec3& normal, double offset);

// The part of a mesh made of its triangles whose three corners are all in `chosen` (0-based
// vertex indices, repeats allowed), as an open mesh: the paper's paste (§4, figure 10: a duck's
// wing cut out and joined to the bunny), the part chosen by the user instead of by a plane.
// Its rim must lie inside the other mesh, as for cutByPlane. Throws std::invalid_argument
// naming the mesh when an index is out of range, when no triangle has all three corners
// chosen, or when the chosen triangles are not one piece (two regions, or regions touching at
// a single vertex: a join takes one seam per side, so paste them one at a time).
LoopShape cutByVertices(const LoopShape& mesh, const std::vector<uint32_t>& chosen);

}  // namespace tessera
