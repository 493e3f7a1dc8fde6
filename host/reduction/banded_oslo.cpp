#include "reduction/banded_oslo.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "bspline/knots.h"
#include "bspline/oslo.h"

namespace tessera {

BandMatrix osloBand(int degree, const std::vector<double>& x, const std::vector<double>& y) {
  const int p = degree;
  const int n = static_cast<int>(x.size()) - p - 1;
  const int m = static_cast<int>(y.size()) - p - 1;
  validateKnots(p, n, x, "coarse knots");
  validateKnots(p, m, y, "fine knots");
  if (!knotsContain(y, x)) {
    throw std::invalid_argument("coarse knots are not contained in the fine knots");
  }
  if (y.front() != x.front() || y.back() != x.back()) {
    throw std::invalid_argument("fine knots reach outside the coarse knots' [x_0, x_last]");
  }
  BandMatrix a;
  a.rows = m;
  a.cols = n;
  a.first.resize(static_cast<size_t>(m));
  a.offset.resize(static_cast<size_t>(m) + 1);
  a.values.resize(static_cast<size_t>(m) * static_cast<size_t>(p + 1));
  for (int j = 0; j < m; ++j) {
    a.offset[static_cast<size_t>(j)] = static_cast<size_t>(j) * static_cast<size_t>(p + 1);
    a.first[static_cast<size_t>(j)] =
        osloRow(p, x, y, j, a.values.data() + a.offset[static_cast<size_t>(j)]);
  }
  a.offset[static_cast<size_t>(m)] = a.values.size();
  return a;
}

BandCholesky factorBand(std::vector<double> g, int n, int p) {
  const size_t w = static_cast<size_t>(p + 1);
  const auto at = [&](int i, int c) -> double& {
    return g[static_cast<size_t>(i) * w + static_cast<size_t>(c - i + p)];
  };
  for (int i = 0; i < n; ++i) {
    for (int c = std::max(0, i - p); c <= i; ++c) {
      double sum = at(i, c);
      for (int q = std::max(0, i - p); q < c; ++q) sum -= at(i, q) * at(c, q);
      if (c < i) {
        at(i, c) = sum / at(c, c);
      } else {
        if (!(sum > 0.0)) {
          throw std::domain_error("band Cholesky: matrix not positive definite at row " +
                                  std::to_string(i));
        }
        at(i, i) = std::sqrt(sum);
      }
    }
  }
  return BandCholesky{n, p, std::move(g)};
}

void BandCholesky::solve(double* b, int columns, size_t stride) const {
  const size_t w = static_cast<size_t>(p + 1);
  const size_t k = static_cast<size_t>(columns);
  const auto lAt = [&](int i, int c) { return l[static_cast<size_t>(i) * w + static_cast<size_t>(c - i + p)]; };
  for (int i = 0; i < n; ++i) {  // L·y = b
    double* bi = b + static_cast<size_t>(i) * stride;
    for (int q = std::max(0, i - p); q < i; ++q) {
      const double f = lAt(i, q);
      const double* bq = b + static_cast<size_t>(q) * stride;
      for (size_t c = 0; c < k; ++c) bi[c] -= f * bq[c];
    }
    const double d = 1.0 / lAt(i, i);
    for (size_t c = 0; c < k; ++c) bi[c] *= d;
  }
  for (int i = n - 1; i >= 0; --i) {  // Lᵀ·z = y
    double* bi = b + static_cast<size_t>(i) * stride;
    for (int q = i + 1; q <= std::min(n - 1, i + p); ++q) {
      const double f = lAt(q, i);
      const double* bq = b + static_cast<size_t>(q) * stride;
      for (size_t c = 0; c < k; ++c) bi[c] -= f * bq[c];
    }
    const double d = 1.0 / lAt(i, i);
    for (size_t c = 0; c < k; ++c) bi[c] *= d;
  }
}

std::vector<double> bandedLeastSquares(const BandMatrix& a, int p, const double* r, int columns) {
  const size_t w = static_cast<size_t>(p + 1);
  const size_t k = static_cast<size_t>(columns);
  std::vector<double> g(static_cast<size_t>(a.cols) * w, 0.0);
  std::vector<double> rhs(static_cast<size_t>(a.cols) * k, 0.0);
  for (int j = 0; j < a.rows; ++j) {
    const double* v = a.values.data() + a.offset[static_cast<size_t>(j)];
    const int f = a.first[static_cast<size_t>(j)];
    const int width = a.width(j);
    const double* rj = r + static_cast<size_t>(j) * k;
    for (int s = 0; s < width; ++s) {
      if (v[s] == 0.0) continue;
      for (int t = 0; t <= s; ++t) {
        g[static_cast<size_t>(f + s) * w + static_cast<size_t>(t - s + p)] += v[s] * v[t];
      }
      double* out = rhs.data() + static_cast<size_t>(f + s) * k;
      for (size_t c = 0; c < k; ++c) out[c] += v[s] * rj[c];
    }
  }
  factorBand(std::move(g), a.cols, p).solve(rhs.data(), columns);
  return rhs;
}

std::vector<glm::dvec3> inverseOsloBanded(int degree, const std::vector<double>& coarseKnots,
                                          const std::vector<double>& fineKnots,
                                          const std::vector<glm::dvec3>& fineCp) {
  const int fineCount = static_cast<int>(fineKnots.size()) - degree - 1;
  if (static_cast<int>(fineCp.size()) != fineCount) {
    throw std::invalid_argument("inverseOsloBanded: " + std::to_string(fineCp.size()) +
                                " control points for " + std::to_string(fineKnots.size()) +
                                " fine knots of degree " + std::to_string(degree) +
                                " (expected " + std::to_string(fineCount) + ")");
  }
  std::vector<double> r;
  r.reserve(fineCp.size() * 3);
  for (size_t k = 0; k < fineCp.size(); ++k) {
    const glm::dvec3& q = fineCp[k];
    if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z)) {
      throw std::invalid_argument("inverseOsloBanded: control point " + std::to_string(k) +
                                  " is not finite");
    }
    r.insert(r.end(), {q.x, q.y, q.z});
  }
  const BandMatrix a = osloBand(degree, coarseKnots, fineKnots);
  const std::vector<double> q = bandedLeastSquares(a, degree, r.data(), 3);
  std::vector<glm::dvec3> out(static_cast<size_t>(a.cols));
  for (size_t i = 0; i < out.size(); ++i) out[i] = {q[3 * i], q[3 * i + 1], q[3 * i + 2]};
  return out;
}

BandMatrix pseudoInverseBand(const BandMatrix& a, int p, double cutoff) {
  const int n = a.cols, m = a.rows;
  // Z = G⁻¹Aᵀ: the least-squares solution for the m unit right-hand sides at once.
  std::vector<double> identity(static_cast<size_t>(m) * static_cast<size_t>(m), 0.0);
  for (int j = 0; j < m; ++j) identity[static_cast<size_t>(j) * m + j] = 1.0;
  const std::vector<double> z = bandedLeastSquares(a, p, identity.data(), m);
  BandMatrix out;
  out.rows = n;
  out.cols = m;
  out.first.resize(static_cast<size_t>(n));
  out.offset.assign(1, 0);
  for (int i = 0; i < n; ++i) {
    const double* row = z.data() + static_cast<size_t>(i) * m;
    double largest = 0.0;
    for (int j = 0; j < m; ++j) largest = std::max(largest, std::abs(row[j]));
    int lo = 0, hi = m - 1;
    while (lo < hi && std::abs(row[lo]) <= cutoff * largest) ++lo;
    while (hi > lo && std::abs(row[hi]) <= cutoff * largest) --hi;
    out.first[static_cast<size_t>(i)] = lo;
    out.values.insert(out.values.end(), row + lo, row + hi + 1);
    out.offset.push_back(out.values.size());
  }
  return out;
}

std::vector<glm::dvec3> applyBandToCurves(const BandMatrix& m, const std::vector<glm::dvec3>& in,
                                          int curves) {
  if (curves < 0 || in.size() != static_cast<size_t>(curves) * static_cast<size_t>(m.cols)) {
    throw std::invalid_argument("applyBandToCurves: " + std::to_string(in.size()) +
                                " points are not " + std::to_string(curves) + " curves of " +
                                std::to_string(m.cols));
  }
  std::vector<glm::dvec3> out(static_cast<size_t>(curves) * static_cast<size_t>(m.rows));
  for (int c = 0; c < curves; ++c) {
    const glm::dvec3* curve = in.data() + static_cast<size_t>(c) * m.cols;
    for (int i = 0; i < m.rows; ++i) {
      glm::dvec3 sum(0.0);
      const double* v = m.values.data() + m.offset[static_cast<size_t>(i)];
      const glm::dvec3* src = curve + m.first[static_cast<size_t>(i)];
      for (int t = 0; t < m.width(i); ++t) sum += v[t] * src[t];
      out[static_cast<size_t>(c) * m.rows + i] = sum;
    }
  }
  return out;
}

}  // namespace tessera
