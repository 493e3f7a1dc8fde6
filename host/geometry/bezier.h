// Polynomial Bézier curves (degree ≤ 7) and tensor-product patches (≤ 7×7) in double:
// evaluation, derivatives, de Casteljau subdivision and sub-patch extraction.
// Control-point order: docs/conventions.md. Invalid degrees or control-point counts throw
// std::invalid_argument; parameters outside [0,1] extrapolate the polynomial.
#pragma once
#include <utility>

#include "geometry/patch.h"

namespace tessera {

// Throw std::invalid_argument unless 1 ≤ degree ≤ kMaxDegree and the count matches.
void validateCurve(const BezierCurve& curve);
void validatePatch(const BezierPatch& patch);

glm::dvec3 curvePoint(const BezierCurve& curve, double t);
// d^order/dt^order P(t); order 0 is the point, order > degree gives zero.
glm::dvec3 curveDerivative(const BezierCurve& curve, double t, int order);
// The pieces of the curve over [0,t] and [t,1], each reparametrised to [0,1].
std::pair<BezierCurve, BezierCurve> subdivideCurve(const BezierCurve& curve, double t);
// The piece over [t0,t1] reparametrised to [0,1] (t0 > t1 reverses it).
BezierCurve subCurve(const BezierCurve& curve, double t0, double t1);

glm::dvec3 patchPoint(const BezierPatch& patch, double u, double v);
// Position and all partials up to third order.
SurfaceDerivatives patchDerivatives(const BezierPatch& patch, double u, double v);
// Its partials up to second order (third-order fields zero), the same doubles, for a patch
// without weights that patchDerivatives accepts: no checks, the CAD import's degrees fixed at
// compile time (geometry/fixed_degrees.h). The closest-point search's evaluation.
SurfaceDerivatives patchSecondDerivativesOfValid(const BezierPatch& patch, double u, double v);
// Split along u at `u` (pieces [0,u]×[0,1] and [u,1]×[0,1]), or along v at `v`.
std::pair<BezierPatch, BezierPatch> subdividePatchU(const BezierPatch& patch, double u);
std::pair<BezierPatch, BezierPatch> subdividePatchV(const BezierPatch& patch, double v);
// The patch over [u0,u1]×[v0,v1] reparametrised to [0,1]².
BezierPatch subPatch(const BezierPatch& patch, double u0, double u1, double v0, double v1);

}  // namespace tessera
