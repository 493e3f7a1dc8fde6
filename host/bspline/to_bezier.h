// Exact conversion of B-spline curves and surfaces to Bézier pieces: every knot in the
// domain [x_p, x_n] is raised to multiplicity p by knot insertion (oslo.h), after which the
// p + 1 control points of each non-empty span are that span's Bézier control points.
#pragma once
#include <utility>
#include <vector>

#include "bspline/bspline.h"
#include "geometry/patch.h"

namespace tessera {

// The Bézier curve is the B-spline on [t0, t1], reparametrised: B(s) = C(t0 + s·(t1 − t0)).
struct BezierCurvePiece {
  BezierCurve curve;
  double t0 = 0.0;
  double t1 = 1.0;
};

// P(s, r) = S(u0 + s·(u1 − u0), v0 + r·(v1 − v0)), control points in BezierPatch order.
struct BezierPatchPiece {
  BezierPatch patch;
  double u0 = 0.0, u1 = 1.0;
  double v0 = 0.0, v1 = 1.0;
};

// The knot vector with every value in [x_p, x_n] at multiplicity ≥ p (knots validated).
std::vector<double> bezierKnots(int degree, const std::vector<double>& knots);

// One piece per non-empty knot span of the domain, in increasing t.
std::vector<BezierCurvePiece> bezierPieces(const BSplineCurve& curve);

// One patch per pair of non-empty spans; the patch of u-span a and v-span b is at
// index a·(number of v-spans) + b, i.e. u-major like the control net.
std::vector<BezierPatchPiece> bezierPatches(const BSplineSurface& surface);

// bezierPatches of `surface` and of `companion`, a second control net on its knots (countU ×
// countV, u-major: a rational surface's weights beside its weighted points), bit for bit what
// two calls give, with the knot insertion's matrices built once. Throws std::invalid_argument
// when `companion` does not fit.
std::pair<std::vector<BezierPatchPiece>, std::vector<BezierPatchPiece>> bezierPatchPair(
    const BSplineSurface& surface, const std::vector<glm::dvec3>& companion);

}  // namespace tessera
