// The directional cell bound of the Directional division method (division_count.h): a bound of
// the parametric deviation of a grid cell's two triangles from the second derivatives along
// the triangles' edge directions, plus a Filip bound of how far S'' strays from a constant over
// the cell. Derivation in division_directional.cpp and docs/rational_division.md.
#pragma once
#include "division/detail/bounds.h"

namespace tessera {

// The largest value of c01·λ0λ1 + c12·λ1λ2 + c02·λ0λ2 over λ ≥ 0, λ0 + λ1 + λ2 = 1 (c ≥ 0),
// rounded up.
double largestSimplexProduct(double c01, double c12, double c02);

// An upper bound of the deviation of both triangles of an h×k cell (diagonal from its (u0, v0)
// corner to its (u1, v1) corner) whose numerators of S'' and w³, restricted to the cell by
// de Casteljau, are `cell` (their values are derivatives in the patch's parameters).
// The cell is bounded whole, then as 2×2, 4×4, ... sub-pieces (`refinement` levels) until the
// bound is ≤ target. INFINITY when W = w³ changes sign on every level tried.
double directionalCellBound(const SecondDerivativeNumerators& cell, double h, double k,
                            int refinement, double target);

}  // namespace tessera
