// Non-rational B-spline curves and surfaces in double precision: Cox–de Boor basis functions,
// their derivatives, and point/derivative evaluation (the CPU reference for B-spline input).
// Knot conventions (span search, right end, domain [x_p, x_n]): knots.h.
#pragma once
#include <array>
#include <glm/glm.hpp>
#include <vector>

#include "geometry/patch.h"

namespace tessera {

// Degree p, n control points, n + p + 1 knots.
struct BSplineCurve {
  int degree = 3;
  std::vector<double> knots;
  std::vector<glm::dvec3> cp;
};

// Tensor-product B-spline surface; cp is countU × countV, row-major, i along u (as BezierPatch).
struct BSplineSurface {
  int degreeU = 3;
  int degreeV = 3;
  std::vector<double> knotsU, knotsV;
  int countU = 0;
  int countV = 0;
  std::vector<glm::dvec3> cp;

  const glm::dvec3& at(int i, int j) const { return cp[static_cast<size_t>(i * countV + j)]; }
  glm::dvec3& at(int i, int j) { return cp[static_cast<size_t>(i * countV + j)]; }
};

// Throw std::invalid_argument naming the reason when knots or control-point counts are
// inconsistent (see validateKnots). The evaluators below only check sizes and assume
// the knots have been validated once.
void validateCurve(const BSplineCurve& curve);
void validateSurface(const BSplineSurface& surface);

// --- Basis functions -------------------------------------------------------------------
// The recursive definition, N_{i,p}(t) (Taniguchi 2000 eq. 12–13 with degree p = k − 1),
// over the whole knot range: half-open intervals [x_i, x_{i+1}), 0/0 taken as 0, except
// that the last non-empty interval is closed at the final knot so the right end evaluates.
// Exponential in p: a reference for tests, not for loops. Any degree ≥ 0.
double basisFunction(int i, int degree, const std::vector<double>& knots, double t);
// d^k/dt^k N_{i,p}(t) by the derivative recurrence
// N'_{i,p} = p·N_{i,p-1}/(x_{i+p} − x_i) − p·N_{i+1,p-1}/(x_{i+p+1} − x_{i+1}).
double basisFunctionDerivative(int i, int degree, const std::vector<double>& knots, double t,
                               int order);

// row[r] = N_{span-p+r, p}(t), r = 0..p: all basis functions nonzero on `span`
// (findSpan), by the triangular scheme of de Boor (no zero denominators on a non-empty span).
// Throws std::invalid_argument unless p ≤ kMaxDegree and span ∈ [p, n-1].
using BasisRow = std::array<double, kMaxDegree + 1>;
BasisRow basisFunctions(int span, int degree, const std::vector<double>& knots, double t);

// table[k][r] = d^k/dt^k N_{span-p+r, p}(t) for k = 0..order; rows above p are zero.
using BasisTable = std::array<BasisRow, kMaxDegree + 1>;
BasisTable basisDerivatives(int span, int degree, const std::vector<double>& knots, double t,
                            int order);

// --- Curves and surfaces --------------------------------------------------------------
// t outside the domain [x_p, x_n] evaluates the polynomial of the nearest end span.
glm::dvec3 curvePoint(const BSplineCurve& curve, double t);

struct BSplineCurveDerivatives {
  glm::dvec3 p, d1, d2;
};
BSplineCurveDerivatives curveDerivatives(const BSplineCurve& curve, double t);

glm::dvec3 surfacePoint(const BSplineSurface& surface, double u, double v);
// Position and partials up to third order (third order feeds the limiting normal at
// degenerate points, docs/conventions.md); orders above a degree are zero.
SurfaceDerivatives surfaceDerivatives(const BSplineSurface& surface, double u, double v);

}  // namespace tessera
