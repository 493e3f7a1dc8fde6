// Exact degree elevation of tensor-product Bézier patches: the same surface written with one
// more control point per row or column, so lower-degree input can be handed to the bicubic
// tessellator unchanged. One step from degree n to n + 1 in a direction (the degree-elevation
// identity of Bézier curves, e.g. Farin, "Curves and Surfaces for CAGD", "Degree elevation"):
//   b'_i = (i/(n+1)) b_{i-1} + (1 − i/(n+1)) b_i,   i = 0..n+1,
// applied to every row (u) or column (v) of the control net; repeated steps reach any higher
// degree. End points are kept, and a boundary curve shared by two patches (in either
// direction) is elevated to bit-identical points, so watertight stitching still finds it.
#pragma once
#include "geometry/patch.h"

namespace tessera {

// Degree (n, m) → (n + 1, m) and (n, m + 1). Throw std::invalid_argument for an invalid
// patch (bezier.h validatePatch) or when the result would exceed kMaxDegree.
BezierPatch elevateDegreeU(const BezierPatch& patch);
BezierPatch elevateDegreeV(const BezierPatch& patch);

// Elevate to (degreeU, degreeV); throws std::invalid_argument when either is below the
// patch's degree or above kMaxDegree.
BezierPatch elevateDegreeTo(const BezierPatch& patch, int degreeU, int degreeV);

}  // namespace tessera
