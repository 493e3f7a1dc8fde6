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
  std::string code;     // "no-triangles", "zero-normals", "flattened-patch", "large-deviation",
                        // "unproven-patch", "diagonal-fan", "fp32-output"
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

// "fp32-output": the mesh goes out in fp32 (it has no positionsDouble, what --precision double
// writes) and fp32 cannot hold the accuracy asked for. Rounding a coordinate of magnitude up to
// M (the largest |control-point coordinate|: the surface lies in their hull) moves it by up to
// e = ½ ulp₃₂(M) (M itself where fp32 flushes it to 0; fp32RoundingBound), a vertex by up to
// √3·e. Warned when √3·e exceeds kFp32OfTolerance·δ (rule T in model units: the rounded mesh
// is then within δ + √3·e, not δ) or, for the other rules, kFp32OfSize of the model's size
// (the control points' diagonal). At rule T's default δ (0.1% of the diagonal) the two agree.
// The teapot (M = 3.5) is far from either; moved by 10⁴ on one axis, it is warned about.
constexpr double kFp32OfTolerance = 0.1;
constexpr double kFp32OfSize = 1e-4;

// The largest error of rounding a number of magnitude ≤ m to fp32 (round to nearest): half its
// spacing at m, 2⁻¹⁵⁰ among the subnormals, m itself where that is less (it rounds to 0), ∞
// beyond fp32's range. From the exponent (frexp), so any double works.
double fp32RoundingBound(double m);

// The conditions, in this order:
//   no-triangles     the mesh has no triangle (every patch collapsed, or an input of nothing);
//   zero-normals     vertices used by a triangle whose normal is the zero vector (written as
//                    "vn 0 0 0": the surface has no tangent plane there and no limit either);
//   flattened-patch  as above (kFlattenedFraction), the patches named;
//   large-deviation  as above, when `geometricPerPatchMax` (one per patch) is given;
//   unproven-patch   rule T (`tolerance` > 0): patches with a leaf whose bound is above δ (it
//                    reached the depth or size limit first: a corner weight of 10⁻²⁰ crowds
//                    the surface into u, v ≲ 10⁻²⁰ there), named;
//   diagonal-fan     rule T: leaves whose bound holds for one diagonal's triangles but that
//                    the triangulator had to fan (TessellationStats::diagonalFans; docs/
//                    quadtree.md, "One diagonal"), counted;
//   fp32-output      as above.
// `tolerance` is rule T's δ in model units, 0 for the other rules (and for a tolerance in
// pixels).
std::vector<ResultWarning> findResultWarnings(
    const Tessellation& tessellation, const std::vector<BezierPatch>& patches,
    const std::vector<double>* geometricPerPatchMax = nullptr, double tolerance = 0);

// The largest distance of kFlatnessSamples² surface points from the plane through the corners'
// centroid normal to the cross product of the diagonals, over surfaceScale (0 when the corners
// span no plane: a patch collapsed to a line or a point is not "flattened").
double cornerPlaneDistanceRatio(const BezierPatch& patch);

}  // namespace tessera
