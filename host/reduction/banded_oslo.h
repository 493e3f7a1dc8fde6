// Banded forms of the Oslo matrix and of its least-squares inverse: what the fast path of the
// control-point reduction (reduction_fast.h) is built from.
//
// Row j of the Oslo matrix A (oslo.h) has at most p + 1 nonzeros, in consecutive columns, so
// A is stored as one first column and p + 1 values per row. The normal matrix G = AᵀA is
// symmetric positive definite (A has full column rank when x ⊂ y) with half-bandwidth p; its
// Cholesky factor keeps the band, and Q = G⁻¹AᵀR is A⁺R in O(m·p·K) for K right-hand sides
// instead of the SVD's O(m·n²). Cholesky is invariant to the diagonal scaling that makes the
// B-spline normal matrix well conditioned (van der Sluis), which is why it meets the SVD to
// 1e-9 (tests/test_knot_removal_fast.cpp).
#pragma once
#include <glm/glm.hpp>
#include <vector>

#include "geometry/patch.h"

namespace tessera {

// A (rows × cols) matrix whose row r holds width(r) values from column first[r] on.
struct BandMatrix {
  int rows = 0, cols = 0;
  std::vector<int> first;       // rows entries
  std::vector<size_t> offset;   // rows + 1 entries: row r is values[offset[r] .. offset[r+1])
  std::vector<double> values;
  int width(int r) const { return static_cast<int>(offset[r + 1] - offset[r]); }
};

// The whole Oslo matrix in band form, rows by osloRow (oslo.h), validated as osloMatrix
// validates.
BandMatrix osloBand(int degree, const std::vector<double>& x, const std::vector<double>& y);

// Cholesky factor of a symmetric positive definite band matrix of half-bandwidth p, stored as
// n × (p + 1): entry (i, k) holds L(i, i − p + k), k = p the diagonal.
struct BandCholesky {
  int n = 0, p = 0;
  std::vector<double> l;
  // Solves G·Z = B in place for the K columns of B (n × K, row-major).
  void solve(double* b, int columns) const { solve(b, columns, static_cast<size_t>(columns)); }
  // The same for K columns of a wider row-major array whose rows are `stride` doubles apart.
  void solve(double* b, int columns, size_t stride) const;
};
// Factors G given in the same n × (p + 1) lower-band layout. Throws std::domain_error when G
// is not positive definite (A was rank deficient: a bug upstream, not bad input).
BandCholesky factorBand(std::vector<double> g, int n, int p);

// Q = A⁺·R for K right-hand sides: R is a.rows × K row-major, the result a.cols × K.
std::vector<double> bandedLeastSquares(const BandMatrix& a, int p, const double* r, int columns);

// Inverse Oslo for one curve through the band (the fast twin of inverseOslo in knot_removal.h,
// same checks and messages).
std::vector<glm::dvec3> inverseOsloBanded(int degree, const std::vector<double>& coarseKnots,
                                          const std::vector<double>& fineKnots,
                                          const std::vector<glm::dvec3>& fineCp);

// A⁺ = G⁻¹Aᵀ explicitly, each row cut to the shortest column range outside which every entry
// is below cutoff × the row's largest (A⁺ is dense but its rows decay exponentially away from
// the diagonal). What the GPU applies to all rows of a direction in one product.
BandMatrix pseudoInverseBand(const BandMatrix& a, int p, double cutoff = 1e-13);

// out (curves × m.rows) = m applied to each curve of `in` (curves × m.cols), both row-major,
// in double: the CPU reference of the GPU product (reduction_vulkan.cpp).
std::vector<glm::dvec3> applyBandToCurves(const BandMatrix& m, const std::vector<glm::dvec3>& in,
                                          int curves);

}  // namespace tessera
