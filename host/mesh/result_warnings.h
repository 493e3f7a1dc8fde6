// A valid mesh that is still not what was asked for: the conditions a run warns about (one
// line on stderr, and the report's "warnings"), each defined precisely here so that a test can
// show both sides of it. None of them is an error: the mesh is written and the run exits 0.
#pragma once
#include <string>
#include <vector>

#include "geometry/patch.h"
#include "mesh/tessellate.h"

namespace tessera {

struct ResultWarning {
  std::string code;     // "no-triangles", "zero-normals", "flattened-patch", "large-deviation"
  std::string message;  // one line naming the cause
};

// A patch's shape is judged from 5×5 samples of the surface; distances are relative to the
// patch's size (surfaceScale: its control net's bounding-box diagonal).
constexpr int kFlatnessSamples = 5;
// "flattened-patch": a patch kept as ≤ 2 triangles (one leaf) although its surface strays
// this far from the plane of its four corners. Rules B–D can stop at the root when the
// samples they test happen to agree (a symmetric bump: equal normals at the corners and the
// centre), and the mesh is then flat where the surface is not.
constexpr double kFlattenedFraction = 0.05;
// "large-deviation" (only when the deviation was measured): a patch's geometric deviation
// above this fraction of its size, whatever rule made it.
constexpr double kLargeDeviationFraction = 0.05;

// The conditions, in this order:
//   no-triangles     the mesh has no triangle (every patch collapsed, or an input of nothing);
//   zero-normals     vertices used by a triangle whose normal is the zero vector (written as
//                    "vn 0 0 0": the surface has no tangent plane there and no limit either);
//   flattened-patch  as above (kFlattenedFraction), the patches named;
//   large-deviation  as above, when `geometricPerPatchMax` (one per patch) is given.
std::vector<ResultWarning> findResultWarnings(const Tessellation& tessellation,
                                              const std::vector<BezierPatch>& patches,
                                              const std::vector<double>* geometricPerPatchMax = nullptr);

// The largest distance of kFlatnessSamples² surface points from the plane through the corners'
// centroid normal to the cross product of the diagonals, over surfaceScale (0 when the corners
// span no plane: a patch collapsed to a line or a point is not "flattened").
double cornerPlaneDistanceRatio(const BezierPatch& patch);

}  // namespace tessera
