// Tensor-product Bernstein polynomials with any coefficient type (double, dvec3, dvec4) and
// the few operations the rational division-count bounds are built from: hodographs, degree
// elevation, products, sub-nets by de Casteljau, evaluation. A curve is a net with m = 0.
// Unlike rational.h, weights here may have any sign: in clip space a control point behind the
// eye has w < 0 and one on the eye plane w = 0 (docs/rational_division.md).
#pragma once
#include <glm/glm.hpp>

#include <vector>

#include "geometry/componentwise.h"
#include "geometry/patch.h"

namespace tessera {

template <class T>
struct BernsteinNet {
  int n = 0;  // degree in u
  int m = 0;  // degree in v (0 for a curve)
  std::vector<T> c;  // c[i*(m+1) + j], i along u (docs/conventions.md)

  BernsteinNet() = default;
  BernsteinNet(int degreeU, int degreeV, T fill = T(0.0))
      : n(degreeU), m(degreeV), c(static_cast<size_t>((degreeU + 1) * (degreeV + 1)), fill) {}
  T& at(int i, int j) { return c[i * (m + 1) + j]; }
  const T& at(int i, int j) const { return c[i * (m + 1) + j]; }
};

using ScalarNet = BernsteinNet<double>;
using VectorNet = BernsteinNet<glm::dvec3>;
using HomogeneousNet = BernsteinNet<glm::dvec4>;

// C(n, k) in double for 0 ≤ n ≤ 64 (exact up to n = 56, which covers degree 3·7 products).
double binomialCoefficient(int n, int k);

HomogeneousNet toNet(const RationalBezierPatch& patch);
HomogeneousNet toNet(const RationalBezierCurve& curve);  // m = 0
RationalBezierPatch toPatch(const HomogeneousNet& net);

ScalarNet weightsOf(const HomogeneousNet& net);
VectorNet numeratorsOf(const HomogeneousNet& net);

// ∂/∂u as a net of bidegree (n−1, m) (n·Δ); the zero net of degree 0 when n = 0. Same for v.
template <class T>
BernsteinNet<T> hodographU(const BernsteinNet<T>& a) {
  if (a.n == 0) return BernsteinNet<T>(0, a.m);
  BernsteinNet<T> d(a.n - 1, a.m);
  for (int i = 0; i < a.n; ++i)
    for (int j = 0; j <= a.m; ++j) d.at(i, j) = double(a.n) * (a.at(i + 1, j) - a.at(i, j));
  return d;
}

template <class T>
BernsteinNet<T> hodographV(const BernsteinNet<T>& a) {
  if (a.m == 0) return BernsteinNet<T>(a.n, 0);
  BernsteinNet<T> d(a.n, a.m - 1);
  for (int i = 0; i <= a.n; ++i)
    for (int j = 0; j < a.m; ++j) d.at(i, j) = double(a.m) * (a.at(i, j + 1) - a.at(i, j));
  return d;
}

// The product of two Bernstein polynomials, of bidegree (a.n + b.n, a.m + b.m):
// c_kl = Σ C(p,i)C(p',k−i)/C(p+p',k) · C(q,j)C(q',l−j)/C(q+q',l) · a_ij b_(k−i)(l−j).
template <class T>
BernsteinNet<T> product(const ScalarNet& a, const BernsteinNet<T>& b) {
  BernsteinNet<T> r(a.n + b.n, a.m + b.m);
  for (int i = 0; i <= a.n; ++i)
    for (int j = 0; j <= a.m; ++j) {
      const double aij = a.at(i, j) * binomialCoefficient(a.n, i) * binomialCoefficient(a.m, j);
      if (aij == 0.0) continue;
      for (int k = 0; k <= b.n; ++k)
        for (int l = 0; l <= b.m; ++l)
          r.at(i + k, j + l) +=
              (aij * binomialCoefficient(b.n, k) * binomialCoefficient(b.m, l)) * b.at(k, l);
    }
  for (int k = 0; k <= r.n; ++k)
    for (int l = 0; l <= r.m; ++l)
      r.at(k, l) = r.at(k, l) / (binomialCoefficient(r.n, k) * binomialCoefficient(r.m, l));
  return r;
}

// Degree elevation to (n2, m2) ≥ (n, m): the product with the constant 1 of degree
// (n2 − n, m2 − m).
template <class T>
BernsteinNet<T> elevate(const BernsteinNet<T>& a, int n2, int m2) {
  if (n2 == a.n && m2 == a.m) return a;
  return product(ScalarNet(n2 - a.n, m2 - a.m, 1.0), a);
}

// a·sa + b·sb for nets of the same bidegree.
template <class T>
BernsteinNet<T> combine(const BernsteinNet<T>& a, double sa, const BernsteinNet<T>& b,
                        double sb) {
  BernsteinNet<T> r(a.n, a.m);
  for (size_t k = 0; k < r.c.size(); ++k) r.c[k] = sa * a.c[k] + sb * b.c[k];
  return r;
}

// The coefficients of one Bernstein polynomial (degree ≤ kMaxNetDegree) restricted to
// [t0, t1] (0 ≤ t0 < t1) and reparametrised to [0, 1], in place: split at t1 keeping the left
// piece, then split that at t0/t1 keeping the right piece (de Casteljau both times).
// `stride` steps between consecutive coefficients.
constexpr int kMaxNetDegree = 4 * kMaxDegree;
template <class T>
void restrictCoefficients(T* p, int degree, int stride, double t0, double t1) {
  T row[kMaxNetDegree + 1] = {};
  T left[kMaxNetDegree + 1] = {};
  for (int k = 0; k <= degree; ++k) row[k] = p[k * stride];
  left[0] = row[0];
  for (int r = 1; r <= degree; ++r) {
    for (int k = 0; k <= degree - r; ++k) row[k] = (1.0 - t1) * row[k] + t1 * row[k + 1];
    left[r] = row[0];
  }
  const double s = t0 / t1;
  for (int k = 0; k <= degree; ++k) row[k] = left[k];
  p[degree * stride] = row[degree];
  for (int r = 1; r <= degree; ++r) {
    for (int k = 0; k <= degree - r; ++k) row[k] = (1.0 - s) * row[k] + s * row[k + 1];
    p[(degree - r) * stride] = row[degree - r];
  }
}

// The net over [u0,u1]×[v0,v1] reparametrised to [0,1]² (u0 < u1, v0 < v1).
template <class T>
BernsteinNet<T> subNet(const BernsteinNet<T>& a, double u0, double u1, double v0, double v1) {
  BernsteinNet<T> r = a;
  if (u0 != 0.0 || u1 != 1.0)
    for (int j = 0; j <= a.m; ++j) restrictCoefficients(&r.at(0, j), a.n, a.m + 1, u0, u1);
  if (v0 != 0.0 || v1 != 1.0)
    for (int i = 0; i <= a.n; ++i) restrictCoefficients(&r.at(i, 0), a.m, 1, v0, v1);
  return r;
}

// The polynomial's value at (u, v): de Casteljau along v in each row, then along u
// (component by component: geometry/componentwise.h).
template <class T>
T evaluate(const BernsteinNet<T>& a, double u, double v) {
  T rows[kMaxNetDegree + 1] = {};
  T col[kMaxNetDegree + 1] = {};
  for (int i = 0; i <= a.n; ++i) {
    for (int j = 0; j <= a.m; ++j) col[j] = a.at(i, j);
    for (int r = 1; r <= a.m; ++r)
      for (int j = 0; j <= a.m - r; ++j) blendInto(col[j], 1.0 - v, col[j], v, col[j + 1]);
    rows[i] = col[0];
  }
  for (int r = 1; r <= a.n; ++r)
    for (int i = 0; i <= a.n - r; ++i) blendInto(rows[i], 1.0 - u, rows[i], u, rows[i + 1]);
  return rows[0];
}

// Position and partials up to second order of the projected (x/w, y/w, z/w) point, for
// weights of any sign; w is the denominator there (the caller decides what w ≤ 0 means).
struct ProjectedSecondDerivatives {
  glm::dvec3 p, pu, pv, puu, puv, pvv;
  double w = 0;
};
ProjectedSecondDerivatives projectedDerivatives(const HomogeneousNet& net, double u, double v);

}  // namespace tessera
