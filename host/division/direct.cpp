// The direct deviation bound (division_direct.h): the deviation of a grid cell's triangles is
// e = L − P/w = E/w with E = w·L − P, a polynomial of bidegree (n+1, m+1) because L is linear
// (bidegree (1,1)). With w elevated to the same bidegree and its coefficients of one strict
// sign, E/w is a convex combination of the ratios E_k/w_k, so ‖e‖ ≤ max_k ‖E_k‖/|w_k|; on
// smaller squares the ratios approach the values, so the bound approaches the sup.
#include "division/detail/direct.h"

#include <algorithm>
#include <cmath>

namespace tessera {
namespace {

// A square of the cell, [u0,u1]×[v0,v1] in the cell's parameters, and the nets of E and w of
// one triangle restricted to it.
struct Square {
  VectorNet e;
  ScalarNet w;
  double u0 = 0, u1 = 1, v0 = 0, v1 = 1;
};

bool oneStrictSign(const ScalarNet& w) {
  const bool positive = std::all_of(w.c.begin(), w.c.end(), [](double x) { return x > 0; });
  const bool negative = std::all_of(w.c.begin(), w.c.end(), [](double x) { return x < 0; });
  return positive || negative;
}

// E = w·L − P and w over the whole cell for the lower triangle (u ≥ v: corners (0,0), (1,0),
// (1,1)) or the upper one (v ≥ u: (0,0), (1,1), (0,1)). False when a corner has w = 0.
bool triangleError(const HomogeneousNet& cell, bool lower, Square& out) {
  const int n = cell.n, m = cell.m;
  glm::dvec3 p[2][2];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const glm::dvec4& h = cell.at(i * n, j * m);  // the net's corners lie on the surface
      if (!(h.w != 0.0)) return false;
      p[i][j] = glm::dvec3(h) / h.w;
    }
  // L is linear, so its bidegree-(1,1) net holds its values at the unit square's corners
  // (outside the triangle they extend it linearly).
  VectorNet linear(1, 1);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      linear.at(i, j) = lower ? p[0][0] + double(i) * (p[1][0] - p[0][0]) +
                                    double(j) * (p[1][1] - p[1][0])
                              : p[0][0] + double(j) * (p[0][1] - p[0][0]) +
                                    double(i) * (p[1][1] - p[0][1]);
  const ScalarNet w = weightsOf(cell);
  out.e = combine(product(w, linear), 1.0, elevate(numeratorsOf(cell), n + 1, m + 1), -1.0);
  out.w = elevate(w, n + 1, m + 1);
  return true;
}

bool meetsTriangle(const Square& s, bool lower) { return lower ? s.u1 > s.v0 : s.v1 > s.u0; }

double largestRatio(const Square& s) {
  double r = 0.0;
  for (size_t k = 0; k < s.w.c.size(); ++k)
    r = std::max(r, glm::length(s.e.c[k]) / std::abs(s.w.c[k]));
  return r * (1.0 + 1e-12);  // rounding must not push a bound below the value
}

// The quarter (a, b) ∈ {0,1}² of a square.
Square quarter(const Square& s, int a, int b) {
  Square q;
  q.e = subNet(s.e, 0.5 * a, 0.5 * (a + 1), 0.5 * b, 0.5 * (b + 1));
  q.w = subNet(s.w, 0.5 * a, 0.5 * (a + 1), 0.5 * b, 0.5 * (b + 1));
  const double um = 0.5 * (s.u0 + s.u1), vm = 0.5 * (s.v0 + s.v1);
  q.u0 = a ? um : s.u0;
  q.u1 = a ? s.u1 : um;
  q.v0 = b ? vm : s.v0;
  q.v1 = b ? s.v1 : vm;
  return q;
}

// A corner of the square that lies in the triangle and deviates more than the tolerance: the
// net's corner coefficients are the values there, so this is a measured failure.
bool cornerExceeds(const Square& s, bool lower, double tolerance) {
  const int n = s.w.n, m = s.w.m;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const double u = i ? s.u1 : s.u0, v = j ? s.v1 : s.v0;
      if (lower ? u < v : v < u) continue;
      const double w = s.w.at(i * n, j * m);
      if (glm::length(s.e.at(i * n, j * m)) > tolerance * std::abs(w)) return true;
    }
  return false;
}

bool squareWithin(const Square& s, bool lower, double tolerance, int depthLeft) {
  if (oneStrictSign(s.w)) {
    if (largestRatio(s) <= tolerance) return true;
    if (cornerExceeds(s, lower, tolerance)) return false;
  }
  if (depthLeft == 0) return false;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const Square q = quarter(s, a, b);
      if (meetsTriangle(q, lower) && !squareWithin(q, lower, tolerance, depthLeft - 1))
        return false;
    }
  return true;
}

double squareBound(const Square& s, bool lower, int depthLeft) {
  if (depthLeft == 0) return oneStrictSign(s.w) ? largestRatio(s) : INFINITY;
  double worst = 0.0;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const Square q = quarter(s, a, b);
      if (meetsTriangle(q, lower)) worst = std::max(worst, squareBound(q, lower, depthLeft - 1));
    }
  return worst;
}

}  // namespace

bool cellDeviationWithin(const HomogeneousNet& cell, double tolerance, int maxDepth) {
  for (bool lower : {true, false}) {
    Square whole;
    if (!triangleError(cell, lower, whole) || !squareWithin(whole, lower, tolerance, maxDepth))
      return false;
  }
  return true;
}

double cellDeviationBound(const HomogeneousNet& cell, int depth) {
  double worst = 0.0;
  for (bool lower : {true, false}) {
    Square whole;
    if (!triangleError(cell, lower, whole)) return INFINITY;
    worst = std::max(worst, squareBound(whole, lower, depth));
  }
  return worst;
}

}  // namespace tessera
