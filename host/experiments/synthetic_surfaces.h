// Synthetic dense B-spline surfaces for the control-point reduction: the paper's shoe last
// (2.3×10⁶ control points) is not public, so this is a shape of the same kind and scale.
//
// syntheticLast: a smooth closed-ish shape in millimetres, about 260 × 95 × 85 mm like a shoe
// last. u runs around the cross-section (the first and last rows of the net coincide: a
// closed seam), v from heel to toe (the ends are small open ovals, not poles, so no curve of
// the net degenerates). The cross-section is an ellipse with a flattened sole; width and
// height vary along the length, the toe springs up. On top of that, local features of several
// sizes, displaced along the cross-section's outward direction:
//   2 bumps σ = 20 mm, height 2.5 mm;   4 bumps σ = 7 mm, 1 mm;
//   8 bumps σ = 2.5 mm, 0.3 mm;        12 bumps σ = 0.9 mm, 0.06 mm;
//   one ridge across the instep, 1.5 mm wide and 0.8 mm high,
// placed by a fixed seed. The net samples the shape at the Greville abscissae of open uniform
// cubic knots (a variation-diminishing approximation: smooth, no wiggles of its own). At
// 1,500 × 1,500 the spacing is about 0.2 mm, fine enough to carry the 0.9 mm features.
#pragma once
#include "bspline/bspline.h"

namespace tessera {

// countU, countV ≥ 4 (cubic in both directions). Throws std::invalid_argument otherwise.
BSplineSurface syntheticLast(int countU, int countV);

// The scale of the paper: 1,500 × 1,500 = 2.25×10⁶ control points.
constexpr int kLargeSurfaceCount = 1500;
// For tests: 40 × 56 control points, small enough for the SVD specification.
BSplineSurface syntheticLastSmall();

// A point of the underlying smooth shape at (u, v) ∈ [0, 1]², in millimetres.
glm::dvec3 syntheticLastPoint(double u, double v);

}  // namespace tessera
