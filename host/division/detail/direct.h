// The direct deviation bound of the Direct division method (division_count.h): no second
// derivatives at all. On a triangle of a grid cell the deviation is e = L − P/w, with L the
// linear interpolant of the corners' projected points and P/w the surface, so e = E/w with
// the polynomial E = w·L − P. Where w's Bernstein coefficients have one strict sign,
// ‖E/w‖ ≤ max_k ‖E_k‖/|w_k| over a common basis (convex hull), and the bound tends to the true
// sup as the cell is cut into smaller squares by de Casteljau. Derivation and measurements:
// docs/rational_division.md.
#pragma once
#include "geometry/homogeneous_net.h"

namespace tessera {

// True when both triangles of the cell (diagonal from local (0,0) to (1,1)) are proven to
// deviate at most `tolerance` from the surface; `cell` is the patch's net restricted to the
// cell. Squares whose hull bound exceeds the tolerance are cut in four, at most `maxDepth`
// times; false as soon as a square corner inside a triangle deviates more (a real failure)
// or when a square at the last depth is still unproven.
bool cellDeviationWithin(const HomogeneousNet& cell, double tolerance, int maxDepth);

// The hull bound of the larger of the two triangles' deviations with the cell cut uniformly
// into 2^depth × 2^depth squares; INFINITY when w's coefficients change sign on a square.
// For tests and measurements; the search uses cellDeviationWithin.
double cellDeviationBound(const HomogeneousNet& cell, int depth);

}  // namespace tessera
