#include "geometry/bernstein.h"

#include <array>
#include <stdexcept>
#include <string>

namespace tessera {

namespace {

void checkDegree(int degree, const char* where) {
  if (degree < 0 || degree > kMaxDegree)
    throw std::invalid_argument(std::string(where) + ": degree " + std::to_string(degree) +
                                " is outside 0.." + std::to_string(kMaxDegree));
}

}  // namespace

void binomialOutOfRange(int n) {
  throw std::invalid_argument("binomial: n = " + std::to_string(n) + " is outside 0.." +
                              std::to_string(2 * kMaxDegree));
}

BernsteinTriangle bernsteinTriangle(int degree, double t) {
  checkDegree(degree, "bernsteinTriangle");
  // B_i,d = (1−t) B_i,d−1 + t B_i−1,d−1: only convex combinations for t ∈ [0,1], so no
  // cancellation (Farin §5.1), unlike expanding the powers.
  BernsteinTriangle tri;
  tri.degree = degree;
  const double s = 1.0 - t;
  tri.b[0][0] = 1.0;
  for (int d = 1; d <= degree; ++d) {
    const auto& prev = tri.b[d - 1];
    auto& row = tri.b[d];
    row[0] = s * prev[0];
    for (int i = 1; i < d; ++i) row[i] = s * prev[i] + t * prev[i - 1];
    row[d] = t * prev[d - 1];
  }
  return tri;
}

void bernsteinBasis(int degree, double t, double* out) {
  const BernsteinTriangle tri = bernsteinTriangle(degree, t);
  for (int i = 0; i <= degree; ++i) out[i] = tri.b[degree][i];
}

void bernsteinDerivative(int degree, int order, double t, double* out) {
  if (order < 0)
    throw std::invalid_argument("bernsteinDerivative: order " + std::to_string(order) +
                                " is negative");
  checkDegree(degree, "bernsteinDerivative");
  for (int i = 0; i <= degree; ++i) out[i] = 0.0;
  if (order > degree) return;
  // d^k B_i,n = n!/(n−k)! Σ_r (−1)^(k−r) C(k,r) B_i−r,n−k (Farin §5.3).
  const BernsteinTriangle tri = bernsteinTriangle(degree - order, t);
  const auto& low = tri.b[degree - order];
  const double scale = fallingFactorial(degree, order);
  for (int i = 0; i <= degree; ++i) {
    double sum = 0.0;
    for (int r = 0; r <= order; ++r) {
      const int idx = i - r;
      if (idx < 0 || idx > degree - order) continue;
      const double sign = ((order - r) % 2 == 0) ? 1.0 : -1.0;
      sum += sign * binomial(order, r) * low[idx];
    }
    out[i] = scale * sum;
  }
}

}  // namespace tessera
