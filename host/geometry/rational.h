// Rational Bézier curves and patches in homogeneous form (w·x, w·y, w·z, w), w ≥ 0.
// Derivatives of the projected point come from those of the homogeneous polynomial by the
// quotient rule generalised to any order (Piegl & Tiller, The NURBS Book, eq. 4.8 and 4.20),
// so patches get the full SurfaceDerivatives, third order included.
// A zero weight is allowed; evaluating where the denominator Σ B w is zero throws
// std::domain_error. Invalid degrees, counts or negative weights throw std::invalid_argument.
#pragma once
#include "geometry/patch.h"

namespace tessera {

void validateRationalCurve(const RationalBezierCurve& curve);
void validateRationalPatch(const RationalBezierPatch& patch);

glm::dvec3 rationalCurvePoint(const RationalBezierCurve& curve, double t);
// d^order/dt^order of the projected curve; order 0 is the point.
glm::dvec3 rationalCurveDerivative(const RationalBezierCurve& curve, double t, int order);

// The homogeneous form (w·b, w) of a BezierPatch; weights 1 when it has none.
RationalBezierPatch toRationalPatch(const BezierPatch& patch);

glm::dvec3 rationalPatchPoint(const RationalBezierPatch& patch, double u, double v);
// Position and all partials up to third order of the projected surface.
SurfaceDerivatives rationalPatchDerivatives(const RationalBezierPatch& patch, double u, double v);
// The same up to second order only (the third-order fields stay zero), bit for bit those of
// rationalPatchDerivatives, at about half its cost: what a closest-point search needs.
SurfaceDerivatives rationalPatchSecondDerivatives(const RationalBezierPatch& patch, double u,
                                                  double v);
// The same for a patch known to be valid (validateRationalPatch passed): the checks of its
// degrees, count and weights left out, its degrees fixed at compile time for the CAD import's
// (geometry/fixed_degrees.h). The same doubles; a zero denominator still throws.
SurfaceDerivatives rationalPatchSecondDerivativesOfValid(const RationalBezierPatch& patch, double u,
                                                         double v);

}  // namespace tessera
