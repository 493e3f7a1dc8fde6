// The unit normal of docs/conventions.md, degenerate points included: where |Pu × Pv| ≤ ε·L²
// it is the limiting direction as (u, v) is approached from inside along d = (½−u, ½−v),
// first order, then second order, else the zero vector ("no normal"), never NaN.
// The fp32 shader version is bicubicNormal in shaders/lib/bicubic_eval.h.
#pragma once
#include "geometry/patch.h"

namespace tessera {

// L is the patch's length scale (controlNetDiagonal); eps = 1e-12 is the double-precision ε.
glm::dvec3 unitNormal(const SurfaceDerivatives& d, double u, double v, double L,
                      double eps = 1e-12);

// L: the diagonal of the control net's axis-aligned bounding box.
double controlNetDiagonal(const BezierPatch& patch);
// For rational patches, the box of the projected points x/w; control points of weight 0 are
// points at infinity with no position and are left out (0 if every weight is 0).
double controlNetDiagonal(const RationalBezierPatch& patch);

}  // namespace tessera
