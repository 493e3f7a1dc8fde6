// The directional cell bound of the Directional division method (division_count.h): a bound of
// the parametric deviation of a grid cell's two triangles from the second derivatives along
// the triangles' edge directions, plus a Filip bound of how far S'' strays from a constant over
// the cell. Derivation in division_directional.cpp and docs/rational_division.md.
#pragma once
#include <algorithm>

#include "division/detail/bounds.h"

namespace tessera {

// The largest value of c01·λ0λ1 + c12·λ1λ2 + c02·λ0λ2 over λ ≥ 0, λ0 + λ1 + λ2 = 1 (c ≥ 0),
// rounded up. Inline: the real-time estimate calls it tens of times per patch and frame.
inline double largestSimplexProduct(double c01, double c12, double c02) {
  // The maximum of a quadratic over the triangle λ ≥ 0, Σλ = 1 lies at a stationary point of
  // its restriction to a vertex (0), an edge (c/4 at the edge's midpoint) or the interior.
  double best = 0.25 * std::max({c01, c12, c02});
  // Interior: C λ = μ·1 with C the symmetric matrix of the c's (zero diagonal); by cofactors
  // λ ∝ (c12(c01 + c02 − c12), c02(c01 + c12 − c02), c01(c02 + c12 − c01)), all positive only
  // when the c's satisfy the strict triangle inequalities, and then the value is μ/2.
  const double l0 = c12 * (c01 + c02 - c12), l1 = c02 * (c01 + c12 - c02),
               l2 = c01 * (c02 + c12 - c01);
  if (l0 > 0 && l1 > 0 && l2 > 0) {
    const double denominator = 2.0 * (c01 * c02 + c01 * c12 + c02 * c12) - c01 * c01 -
                               c02 * c02 - c12 * c12;
    if (denominator > 0) best = std::max(best, c01 * c02 * c12 / denominator);
  }
  return best * (1.0 + 1e-12);  // rounding must not push a bound below the value
}

// An upper bound of the deviation of both triangles of an h×k cell (diagonal from its (u0, v0)
// corner to its (u1, v1) corner) whose numerators of S'' and w³, restricted to the cell by
// de Casteljau, are `cell` (their values are derivatives in the patch's parameters).
// The cell is bounded whole, then as 2×2, 4×4, ... sub-pieces (`refinement` levels) until the
// bound is ≤ target. INFINITY when W = w³ changes sign on every level tried.
double directionalCellBound(const SecondDerivativeNumerators& cell, double h, double k,
                            int refinement, double target);

}  // namespace tessera
