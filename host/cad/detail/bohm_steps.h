// BSplCLib::Bohm (OCCT 7.6) in its two steps, for IsoLineD1: the first (divided differences of
// the poles) does not depend on the parameter, so a span's can be kept between evaluations; the
// second (nested multiplication at the parameter, then the degree factors) is all a call needs
// then. The same operations in the same order as Bohm for a dimension of 2 or more (Bohm's one-
// dimensional branch divides where these multiply by the reciprocal): the same bits, which the
// test checks against Bohm itself.
#pragma once

namespace tessera::cad_detail {

// Bohm's first step on degree + 1 points of `dimension` numbers each: point j + 1 becomes the
// divided difference (P[j+1] − P[j]) / (knot[j + degree − i] − knot[j]), as the reciprocal's
// product (0 where the two knots are equal), for i = 0 … degree − 1 and j from degree − 1 down
// to i. `knots`: the span's 2·degree knots (BSplCLib::BuildKnots).
inline void bohmDifferences(int degree, const double* knots, int dimension, double* poles) {
  for (int i = 0; i < degree; ++i)
    for (int j = degree - 1; j >= i; --j) {
      const double a = knots[j + degree - i], b = knots[j];
      const double coef = a == b ? 0.0 : 1. / (a - b);
      double* pole = poles + (j + 1) * dimension;
      const double* previous = poles + j * dimension;
      for (int k = 0; k < dimension; ++k) {
        pole[k] -= previous[k];
        pole[k] *= coef;
      }
    }
}

// Bohm's second step at `u` on bohmDifferences' result: P[j] += (u − knot[i])·P[j+1] for
// i = 0 … degree − 1 and j from i down to 0, then derivative n (n = 1 … min(derivatives,
// degree)) times degree·(degree − 1)·…·(degree − n + 1). Point 0 is then the value, point n the
// n-th derivative.
inline void bohmAt(double u, int degree, int derivatives, const double* knots, int dimension,
                   double* poles) {
  for (int i = 0; i < degree; ++i) {
    const double coef = u - knots[i];
    for (int j = i; j >= 0; --j) {
      double* pole = poles + j * dimension;
      const double* next = pole + dimension;
      for (int k = 0; k < dimension; ++k) pole[k] += coef * next[k];
    }
  }
  double factor = degree;
  int remaining = degree;
  const int orders = derivatives < degree ? derivatives : degree;
  for (int n = 1; n <= orders; ++n) {
    double* pole = poles + n * dimension;
    for (int k = 0; k < dimension; ++k) pole[k] *= factor;
    --remaining;
    factor *= remaining;
  }
}

}  // namespace tessera::cad_detail
