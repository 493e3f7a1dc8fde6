// Bernstein polynomials B_i,n(t) = C(n,i) t^i (1−t)^(n−i) for n ≤ kMaxDegree, their
// derivatives, and the tensor-product sums that every Bézier evaluator in host/ is built on.
#pragma once
#include <array>

#include "geometry/componentwise.h"
#include "geometry/patch.h"

namespace tessera {

namespace bernstein_detail {
// C(n, k) for n ≤ 2·kMaxDegree, each by the product below (every partial product an integer,
// so exact): a table, since the derivative quotient rules ask for it in their inner loops.
constexpr int kBinomialRows = 2 * kMaxDegree + 1;
constexpr std::array<std::array<double, kBinomialRows>, kBinomialRows> binomialTable() {
  std::array<std::array<double, kBinomialRows>, kBinomialRows> table{};
  for (int n = 0; n < kBinomialRows; ++n)
    for (int k = 0; k <= n; ++k) {
      double c = 1.0;
      for (int i = 1; i <= k; ++i) c = c * (n - k + i) / i;
      table[n][k] = c;
    }
  return table;
}
inline constexpr auto kBinomials = binomialTable();
}  // namespace bernstein_detail

[[noreturn]] void binomialOutOfRange(int n);  // throws std::invalid_argument

// C(n, k) for 0 ≤ n ≤ 2·kMaxDegree (exact in double); 0 when k < 0 or k > n. Inline: the
// rational derivatives' quotient rule asks for it in its inner loop (a call and the range
// check were 2.6% of the trimmed mesher's cut on a B-spline-heavy model, callgrind).
inline double binomial(int n, int k) {
  if (n < 0 || n > 2 * kMaxDegree) binomialOutOfRange(n);
  if (k < 0 || k > n) return 0.0;
  return bernstein_detail::kBinomials[n][k];
}

// out[i] = B_i,degree(t), i = 0..degree; 0 ≤ degree ≤ kMaxDegree.
void bernsteinBasis(int degree, double t, double* out);

// out[i] = d^order/dt^order B_i,degree(t), i = 0..degree; all zero when order > degree.
void bernsteinDerivative(int degree, int order, double t, double* out);

// Every row of the de Casteljau triangle: b[d][i] = B_i,d(t) for d = 0..degree.
// Derivatives are taken in difference form, d^k/dt^k Σ B_i,n b_i = n!/(n−k)! Σ B_i,n−k Δ^k b_i
// (Farin, Curves and Surfaces for CAGD, §5.3), which needs the lower rows.
// Only b[d][0..d] for d ≤ degree are written and read: the rest is left unset (zeroing all
// 64 doubles was most of a bicubic point's Bernstein values, which the triangulator's
// near-point tests evaluate a few hundred of a mesh).
struct BernsteinTriangle {
  int degree = 0;
  std::array<std::array<double, kMaxDegree + 1>, kMaxDegree + 1> b;
};
BernsteinTriangle bernsteinTriangle(int degree, double t);

// n!/(n−k)!: the factor in front of the k-th hodograph (inline: at fixed degrees the partials'
// factors fold to constants, the same exact integers).
inline double fallingFactorial(int n, int k) {
  double f = 1.0;
  for (int i = 0; i < k; ++i) f *= n - i;
  return f;
}

namespace bernstein_detail {

// One more first difference in u (step r, r = 0, 1, …) of the net in `diff`, in place: exact
// zero stays exact zero. Here and below component by component (geometry/componentwise.h:
// glm's operators cost a checked memcpy a step under AddressSanitizer).
// N, M ≥ 0 fix n and m at compile time (geometry/fixed_degrees.h): the same operations.
template <int N = -1, int M = -1, class Point>
void differenceInU(Point* diff, int n, int m, int r) {
  if constexpr (N >= 0) n = N;
  if constexpr (M >= 0) m = M;
  const int stride = m + 1;
  for (int i = 0; i < n - r; ++i)
    for (int j = 0; j <= m; ++j)
      differenceInto(diff[i * stride + j], diff[(i + 1) * stride + j]);
}

// From the net's a-th differences in u (rows 0..n−a of `diff`): b differences in v, in place,
// then the sum against the Bernstein rows of degree n − a and m − b, times n!/(n−a)!·m!/(m−b)!.
template <int N = -1, int M = -1, class Point>
Point partialFromUDifferences(Point* diff, int n, int m, int a, int b, const BernsteinTriangle& bu,
                              const BernsteinTriangle& bv) {
  if constexpr (N >= 0) n = N;
  if constexpr (M >= 0) m = M;
  const int stride = m + 1;
  for (int r = 0; r < b; ++r)
    for (int i = 0; i <= n - a; ++i)
      for (int j = 0; j < m - r; ++j)
        differenceInto(diff[i * stride + j], diff[i * stride + j + 1]);
  const auto& rowU = bu.b[n - a];
  const auto& rowV = bv.b[m - b];
  Point sum(0.0);
  for (int i = 0; i <= n - a; ++i) {
    Point row(0.0);
    for (int j = 0; j <= m - b; ++j) addScaled(row, rowV[j], diff[i * stride + j]);
    addScaled(sum, rowU[i], row);
  }
  return (fallingFactorial(n, a) * fallingFactorial(m, b)) * sum;
}

}  // namespace bernstein_detail

// ∂^(a+b)/∂u^a ∂v^b of Σ_i Σ_j B_i,n(u) B_j,m(v) net[i*(m+1)+j], in difference form.
// Differences of equal control points are exactly zero, so a collapsed edge gets exactly zero
// tangents — the degenerate-normal rule (docs/conventions.md) depends on that; summing
// derivative weights instead leaves rounding noise of size ε·|b|. Point: glm::dvec3 or dvec4;
// bu and bv are the triangles of degree n at u and m at v.
template <class Point>
Point tensorPartial(const Point* net, int n, int m, int a, int b, const BernsteinTriangle& bu,
                    const BernsteinTriangle& bv) {
  if (a > n || b > m) return Point(0.0);
  std::array<Point, (kMaxDegree + 1) * (kMaxDegree + 1)> diff;
  for (int k = 0; k < (n + 1) * (m + 1); ++k) diff[k] = net[k];
  for (int r = 0; r < a; ++r) bernstein_detail::differenceInU(diff.data(), n, m, r);
  return bernstein_detail::partialFromUDifferences(diff.data(), n, m, a, b, bu, bv);
}

// Every partial with a + b ≤ Order at once: out[a][b] is tensorPartial(net, n, m, a, b, bu, bv)
// bit for bit (the same differences in the same order), from one table of u-differences
// stepped once per a instead of a fresh copy of the net per partial. Evaluating derivatives
// called tensorPartial ten times a point; under AddressSanitizer each call's 2 KB table made the
// trimmed-face tests 16-23x slower than in Release. N, M ≥ 0: n and m fixed at compile time
// (the closest-point search's derivatives), the same doubles.
template <class Point, int Order, int N = -1, int M = -1>
void tensorPartials(const Point* net, int n, int m, const BernsteinTriangle& bu,
                    const BernsteinTriangle& bv, Point (&out)[Order + 1][Order + 1]) {
  if constexpr (N >= 0) n = N;
  if constexpr (M >= 0) m = M;
  constexpr int kSize = (kMaxDegree + 1) * (kMaxDegree + 1);
  const int count = (n + 1) * (m + 1);
  std::array<Point, kSize> inU;    // the net's a-th differences in u
  std::array<Point, kSize> inUV;   // then b differences in v
  for (int k = 0; k < count; ++k) inU[k] = net[k];
  for (int a = 0; a <= Order; ++a) {
    if (a > 0 && a <= n) bernstein_detail::differenceInU<N, M>(inU.data(), n, m, a - 1);
    for (int b = 0; a + b <= Order; ++b) {
      if (a > n || b > m) {
        out[a][b] = Point(0.0);
      } else if (b == 0) {  // no v-differences: the u-table is read, not changed
        out[a][b] = bernstein_detail::partialFromUDifferences<N, M>(inU.data(), n, m, a, 0, bu, bv);
      } else {
        for (int k = 0; k < (n - a + 1) * (m + 1); ++k) inUV[k] = inU[k];
        out[a][b] = bernstein_detail::partialFromUDifferences<N, M>(inUV.data(), n, m, a, b, bu, bv);
      }
    }
  }
}

}  // namespace tessera
