#include "geometry/rational.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/bernstein.h"
#include "geometry/fixed_degrees.h"

namespace tessera {

namespace {

void checkWeights(const std::vector<glm::dvec4>& cpw, const char* where) {
  for (size_t k = 0; k < cpw.size(); ++k) {
    const double w = cpw[k].w;
    if (!(w >= 0.0) || !std::isfinite(w))
      throw std::invalid_argument(std::string(where) + ": weight " + std::to_string(w) +
                                  " of control point " + std::to_string(k) +
                                  " is not a finite number ≥ 0");
  }
}

void checkCurve(const RationalBezierCurve& c, const char* where) {
  if (c.degree < 1 || c.degree > kMaxDegree)
    throw std::invalid_argument(std::string(where) + ": curve degree " + std::to_string(c.degree) +
                                " is outside 1.." + std::to_string(kMaxDegree));
  if (c.cpw.size() != static_cast<size_t>(c.degree + 1))
    throw std::invalid_argument(std::string(where) + ": a degree-" + std::to_string(c.degree) +
                                " curve needs " + std::to_string(c.degree + 1) +
                                " control points, got " + std::to_string(c.cpw.size()));
  checkWeights(c.cpw, where);
}

void checkPatch(const RationalBezierPatch& p, const char* where) {
  if (p.degreeU < 1 || p.degreeU > kMaxDegree || p.degreeV < 1 || p.degreeV > kMaxDegree)
    throw std::invalid_argument(std::string(where) + ": patch degree (" +
                                std::to_string(p.degreeU) + ", " + std::to_string(p.degreeV) +
                                ") is outside 1.." + std::to_string(kMaxDegree) + " in u or v");
  const size_t expected = static_cast<size_t>((p.degreeU + 1) * (p.degreeV + 1));
  if (p.cpw.size() != expected)
    throw std::invalid_argument(std::string(where) + ": a degree-(" + std::to_string(p.degreeU) +
                                ", " + std::to_string(p.degreeV) + ") patch needs " +
                                std::to_string(expected) + " control points, got " +
                                std::to_string(p.cpw.size()));
  checkWeights(p.cpw, where);
}

glm::dvec3 xyz(const glm::dvec4& h) { return glm::dvec3(h.x, h.y, h.z); }

// The homogeneous point's w is the denominator; zero there means the point is at infinity
// (or undefined), which a caller must avoid, e.g. by splitting (Kawasaki et al., B1..B8).
bool denominatorUsable(double w) { return w != 0.0 && std::isfinite(w); }

[[noreturn]] void throwDenominator(const char* where, double w, const std::string& at) {
  throw std::domain_error(std::string(where) + ": the denominator Σ B·w is " + std::to_string(w) +
                          " at " + at);
}

void checkDenominator(double w, const char* where, double t) {
  if (!denominatorUsable(w)) throwDenominator(where, w, "t = " + std::to_string(t));
}

void checkDenominator(double w, const char* where, double u, double v) {
  if (!denominatorUsable(w))
    throwDenominator(where, w, "(u, v) = (" + std::to_string(u) + ", " + std::to_string(v) + ")");
}

// d^k/dt^k of the projected curve for k = 0..order.
std::vector<glm::dvec3> curveDerivatives(const RationalBezierCurve& curve, double t, int order,
                                         const char* where) {
  checkCurve(curve, where);
  if (order < 0)
    throw std::invalid_argument(std::string(where) + ": order " + std::to_string(order) +
                                " is negative");
  const BernsteinTriangle bt = bernsteinTriangle(curve.degree, t);
  const BernsteinTriangle one = bernsteinTriangle(0, 0.0);
  std::vector<glm::dvec4> h(order + 1);
  for (int k = 0; k <= order; ++k)
    h[k] = tensorPartial(curve.cpw.data(), curve.degree, 0, k, 0, bt, one);
  checkDenominator(h[0].w, where, t);

  // C^(k) = (A^(k) − Σ_{i=1..k} C(k,i) w^(i) C^(k−i)) / w (The NURBS Book, eq. 4.8).
  std::vector<glm::dvec3> c(order + 1);
  std::vector<double> pascal{1.0};  // row k of Pascal's triangle: C(k, i)
  for (int k = 0; k <= order; ++k) {
    if (k > 0) {
      std::vector<double> next(k + 1, 1.0);
      for (int i = 1; i < k; ++i) next[i] = pascal[i - 1] + pascal[i];
      pascal.swap(next);
    }
    glm::dvec3 numerator = xyz(h[k]);
    for (int i = 1; i <= k; ++i) numerator -= (pascal[i] * h[i].w) * c[k - i];
    c[k] = numerator / h[0].w;
  }
  return c;
}

}  // namespace

void validateRationalCurve(const RationalBezierCurve& curve) {
  checkCurve(curve, "validateRationalCurve");
}
void validateRationalPatch(const RationalBezierPatch& patch) {
  checkPatch(patch, "validateRationalPatch");
}

glm::dvec3 rationalCurvePoint(const RationalBezierCurve& curve, double t) {
  return curveDerivatives(curve, t, 0, "rationalCurvePoint")[0];
}

glm::dvec3 rationalCurveDerivative(const RationalBezierCurve& curve, double t, int order) {
  return curveDerivatives(curve, t, order, "rationalCurveDerivative").back();
}

RationalBezierPatch toRationalPatch(const BezierPatch& patch) {
  RationalBezierPatch r;
  r.degreeU = patch.degreeU;
  r.degreeV = patch.degreeV;
  r.cpw.reserve(patch.cp.size());
  for (size_t k = 0; k < patch.cp.size(); ++k) {
    const double w = patch.weights.empty() ? 1.0 : patch.weights.at(k);
    r.cpw.push_back(glm::dvec4(patch.cp[k] * w, w));
  }
  return r;
}

glm::dvec3 rationalPatchPoint(const RationalBezierPatch& patch, double u, double v) {
  checkPatch(patch, "rationalPatchPoint");
  const BernsteinTriangle bu = bernsteinTriangle(patch.degreeU, u);
  const BernsteinTriangle bv = bernsteinTriangle(patch.degreeV, v);
  const glm::dvec4 h = tensorPartial(patch.cpw.data(), patch.degreeU, patch.degreeV, 0, 0, bu, bv);
  checkDenominator(h.w, "rationalPatchPoint", u, v);
  return xyz(h) / h.w;
}

namespace {

// Partials up to Order (2 or 3) of the projected surface; those up to second order are the
// same doubles either way (tensorPartials' lower partials and eq. 4.20's lower terms do not
// depend on Order).
// Checked = false: the patch is known to pass checkPatch (the caller checked it once), and the
// degrees N × M (−1: at run time) are its own.
template <int Order, bool Checked = true, int N = -1, int M = -1>
SurfaceDerivatives projectedPartials(const RationalBezierPatch& patch, double u, double v,
                                     const char* where) {
  if constexpr (Checked) checkPatch(patch, where);
  const BernsteinTriangle bu = bernsteinTriangle(patch.degreeU, u);
  const BernsteinTriangle bv = bernsteinTriangle(patch.degreeV, v);
  glm::dvec4 h[Order + 1][Order + 1];  // homogeneous partials, a + b ≤ Order
  tensorPartials<glm::dvec4, Order, N, M>(patch.cpw.data(), patch.degreeU, patch.degreeV, bu, bv,
                                          h);
  checkDenominator(h[0][0].w, where, u, v);

  // S^(a,b) = (A^(a,b) − Σ_{(i,j)≠(0,0)} C(a,i) C(b,j) w^(i,j) S^(a−i,b−j)) / w
  // (The NURBS Book, eq. 4.20); every S on the right has a smaller total order.
  glm::dvec3 s[Order + 1][Order + 1];
  for (int total = 0; total <= Order; ++total)
    for (int a = total; a >= 0; --a) {
      const int b = total - a;
      glm::dvec3 numerator = xyz(h[a][b]);
      for (int i = 0; i <= a; ++i)
        for (int j = 0; j <= b; ++j)
          if (i + j > 0)
            numerator -= (binomial(a, i) * binomial(b, j) * h[i][j].w) * s[a - i][b - j];
      s[a][b] = numerator / h[0][0].w;
    }

  return surfaceDerivativesFrom<Order>(s);
}

}  // namespace

SurfaceDerivatives rationalPatchDerivatives(const RationalBezierPatch& patch, double u, double v) {
  return projectedPartials<3>(patch, u, v, "rationalPatchDerivatives");
}

SurfaceDerivatives rationalPatchSecondDerivatives(const RationalBezierPatch& patch, double u,
                                                  double v) {
  return projectedPartials<2>(patch, u, v, "rationalPatchSecondDerivatives");
}

SurfaceDerivatives rationalPatchSecondDerivativesOfValid(const RationalBezierPatch& patch, double u,
                                                         double v) {
  return withFixedDegrees(patch.degreeU, patch.degreeV, [&](auto N, auto M) {
    return projectedPartials<2, false, decltype(N)::value, decltype(M)::value>(
        patch, u, v, "rationalPatchSecondDerivatives");
  });
}

}  // namespace tessera
