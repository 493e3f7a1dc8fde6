#include "geometry/bezier.h"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "geometry/bernstein.h"
#include "geometry/fixed_degrees.h"
#include "geometry/rational.h"

namespace tessera {

namespace {

using Polygon = std::array<glm::dvec3, kMaxDegree + 1>;

std::string degreeRange() { return "1.." + std::to_string(kMaxDegree); }

void checkCurve(const BezierCurve& c, const char* where) {
  if (c.degree < 1 || c.degree > kMaxDegree)
    throw std::invalid_argument(std::string(where) + ": curve degree " + std::to_string(c.degree) +
                                " is outside " + degreeRange());
  if (c.cp.size() != static_cast<size_t>(c.degree + 1))
    throw std::invalid_argument(std::string(where) + ": a degree-" + std::to_string(c.degree) +
                                " curve needs " + std::to_string(c.degree + 1) +
                                " control points, got " + std::to_string(c.cp.size()));
}

void checkPatch(const BezierPatch& p, const char* where) {
  if (!p.weights.empty())
    throw std::invalid_argument(std::string(where) +
                                ": the patch has weights; it is a rational patch (rational.h)");
  if (p.degreeU < 1 || p.degreeU > kMaxDegree || p.degreeV < 1 || p.degreeV > kMaxDegree)
    throw std::invalid_argument(std::string(where) + ": patch degree (" +
                                std::to_string(p.degreeU) + ", " + std::to_string(p.degreeV) +
                                ") is outside " + degreeRange() + " in u or v");
  const size_t expected = static_cast<size_t>((p.degreeU + 1) * (p.degreeV + 1));
  if (p.cp.size() != expected)
    throw std::invalid_argument(std::string(where) + ": a degree-(" + std::to_string(p.degreeU) +
                                ", " + std::to_string(p.degreeV) + ") patch needs " +
                                std::to_string(expected) + " control points, got " +
                                std::to_string(p.cp.size()));
}

void checkFinite(double t, const char* where) {
  if (!std::isfinite(t))
    throw std::invalid_argument(std::string(where) + ": parameter is not finite");
}

// de Casteljau split of the n+1 points in[k*stride] at t (Farin §3.1); the outputs use the
// same stride, so a patch column or row maps onto the same column or row of each half.
void splitPolygon(const glm::dvec3* in, int stride, int n, double t, glm::dvec3* left,
                  glm::dvec3* right) {
  Polygon w{};
  for (int k = 0; k <= n; ++k) w[k] = in[k * stride];
  left[0] = w[0];
  right[n * stride] = w[n];
  for (int r = 1; r <= n; ++r) {
    for (int i = 0; i <= n - r; ++i) w[i] = (1.0 - t) * w[i] + t * w[i + 1];
    left[r * stride] = w[0];
    right[(n - r) * stride] = w[n - r];
  }
}

// Control points of the piece over [t0,t1]: the blossom values b[t0^(n−k), t1^k]
// (Ramshaw 1987; Farin §4.3), each a de Casteljau run with k steps at t1 and n−k at t0.
// Works for any t0, t1, so sub-patches need no chain of splits and renormalisations.
void segmentPolygon(const glm::dvec3* in, int stride, int n, double t0, double t1,
                    glm::dvec3* out) {
  for (int k = 0; k <= n; ++k) {
    Polygon w{};
    for (int i = 0; i <= n; ++i) w[i] = in[i * stride];
    for (int r = 0; r < n; ++r) {
      const double t = r < k ? t1 : t0;
      for (int i = 0; i < n - r; ++i) w[i] = (1.0 - t) * w[i] + t * w[i + 1];
    }
    out[k * stride] = w[0];
  }
}

}  // namespace

void validateCurve(const BezierCurve& curve) { checkCurve(curve, "validateCurve"); }
void validatePatch(const BezierPatch& patch) { checkPatch(patch, "validatePatch"); }

glm::dvec3 curvePoint(const BezierCurve& curve, double t) {
  checkCurve(curve, "curvePoint");
  const BernsteinTriangle bt = bernsteinTriangle(curve.degree, t);
  const BernsteinTriangle one = bernsteinTriangle(0, 0.0);
  // A curve is a patch of degree (n, 0).
  return tensorPartial(curve.cp.data(), curve.degree, 0, 0, 0, bt, one);
}

glm::dvec3 curveDerivative(const BezierCurve& curve, double t, int order) {
  checkCurve(curve, "curveDerivative");
  if (order < 0)
    throw std::invalid_argument("curveDerivative: order " + std::to_string(order) + " is negative");
  if (order > curve.degree) return glm::dvec3(0.0);
  const BernsteinTriangle bt = bernsteinTriangle(curve.degree, t);
  const BernsteinTriangle one = bernsteinTriangle(0, 0.0);
  return tensorPartial(curve.cp.data(), curve.degree, 0, order, 0, bt, one);
}

std::pair<BezierCurve, BezierCurve> subdivideCurve(const BezierCurve& curve, double t) {
  checkCurve(curve, "subdivideCurve");
  checkFinite(t, "subdivideCurve");
  std::pair<BezierCurve, BezierCurve> halves;
  for (BezierCurve* h : {&halves.first, &halves.second}) {
    h->degree = curve.degree;
    h->cp.resize(curve.cp.size());
  }
  splitPolygon(curve.cp.data(), 1, curve.degree, t, halves.first.cp.data(),
               halves.second.cp.data());
  return halves;
}

BezierCurve subCurve(const BezierCurve& curve, double t0, double t1) {
  checkCurve(curve, "subCurve");
  checkFinite(t0, "subCurve");
  checkFinite(t1, "subCurve");
  BezierCurve piece{curve.degree, std::vector<glm::dvec3>(curve.cp.size())};
  segmentPolygon(curve.cp.data(), 1, curve.degree, t0, t1, piece.cp.data());
  return piece;
}

glm::dvec3 patchPoint(const BezierPatch& patch, double u, double v) {
  if (!patch.weights.empty()) return rationalPatchPoint(toRationalPatch(patch), u, v);
  checkPatch(patch, "patchPoint");
  const BernsteinTriangle bu = bernsteinTriangle(patch.degreeU, u);
  const BernsteinTriangle bv = bernsteinTriangle(patch.degreeV, v);
  // Loops compiled for the usual degrees (fixed_degrees.h), the same doubles as tensorPartial:
  // the triangulator's near-point tests evaluate a few hundred points a mesh.
  glm::dvec3 point[1][1];
  withFixedDegrees(patch.degreeU, patch.degreeV, [&](auto N, auto M) {
    tensorPartials<glm::dvec3, 0, decltype(N)::value, decltype(M)::value>(
        patch.cp.data(), patch.degreeU, patch.degreeV, bu, bv, point);
  });
  return point[0][0];
}

SurfaceDerivatives patchDerivatives(const BezierPatch& patch, double u, double v) {
  if (!patch.weights.empty()) return rationalPatchDerivatives(toRationalPatch(patch), u, v);
  checkPatch(patch, "patchDerivatives");
  const BernsteinTriangle bu = bernsteinTriangle(patch.degreeU, u);
  const BernsteinTriangle bv = bernsteinTriangle(patch.degreeV, v);
  glm::dvec3 partial[4][4];  // a + b ≤ 3
  tensorPartials<glm::dvec3, 3>(patch.cp.data(), patch.degreeU, patch.degreeV, bu, bv, partial);
  return surfaceDerivativesFrom<3>(partial);
}

SurfaceDerivatives patchSecondDerivativesOfValid(const BezierPatch& patch, double u, double v) {
  const BernsteinTriangle bu = bernsteinTriangle(patch.degreeU, u);
  const BernsteinTriangle bv = bernsteinTriangle(patch.degreeV, v);
  glm::dvec3 partial[3][3];  // a + b ≤ 2: tensorPartials' lower partials do not depend on Order
  withFixedDegrees(patch.degreeU, patch.degreeV, [&](auto N, auto M) {
    tensorPartials<glm::dvec3, 2, decltype(N)::value, decltype(M)::value>(
        patch.cp.data(), patch.degreeU, patch.degreeV, bu, bv, partial);
  });
  return surfaceDerivativesFrom<2>(partial);
}

std::pair<BezierPatch, BezierPatch> subdividePatchU(const BezierPatch& patch, double u) {
  checkPatch(patch, "subdividePatchU");
  checkFinite(u, "subdividePatchU");
  std::pair<BezierPatch, BezierPatch> halves{patch, patch};
  const int stride = patch.degreeV + 1;
  for (int j = 0; j <= patch.degreeV; ++j)
    splitPolygon(&patch.cp[j], stride, patch.degreeU, u, &halves.first.cp[j], &halves.second.cp[j]);
  return halves;
}

std::pair<BezierPatch, BezierPatch> subdividePatchV(const BezierPatch& patch, double v) {
  checkPatch(patch, "subdividePatchV");
  checkFinite(v, "subdividePatchV");
  std::pair<BezierPatch, BezierPatch> halves{patch, patch};
  const int stride = patch.degreeV + 1;
  for (int i = 0; i <= patch.degreeU; ++i)
    splitPolygon(&patch.cp[i * stride], 1, patch.degreeV, v, &halves.first.cp[i * stride],
                 &halves.second.cp[i * stride]);
  return halves;
}

BezierPatch subPatch(const BezierPatch& patch, double u0, double u1, double v0, double v1) {
  checkPatch(patch, "subPatch");
  for (double t : {u0, u1, v0, v1}) checkFinite(t, "subPatch");
  const int stride = patch.degreeV + 1;
  BezierPatch alongU = patch;  // the u-restriction, then restricted along v
  for (int j = 0; j <= patch.degreeV; ++j)
    segmentPolygon(&patch.cp[j], stride, patch.degreeU, u0, u1, &alongU.cp[j]);
  BezierPatch piece = alongU;
  for (int i = 0; i <= patch.degreeU; ++i)
    segmentPolygon(&alongU.cp[i * stride], 1, patch.degreeV, v0, v1, &piece.cp[i * stride]);
  return piece;
}

}  // namespace tessera
