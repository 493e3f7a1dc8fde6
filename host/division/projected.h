// Division counts for the real-time path (host/realtime/frame.h), from a patch's screen-space
// homogeneous net in one pass over its control points (docs/realtime.md, "Counts"): a proven
// bound of the screen-space deviation of a uniform grid (Filip's form; in the affine limit,
// all weights equal, Filip's polynomial bound of the projected control points), and a
// directional estimate of it that is not a bound but needs about half the triangles. Both far
// cheaper than `split`.
#pragma once
#include <glm/glm.hpp>

#include <array>

#include "division/count.h"

namespace tessera {

// `net`: (degreeU + 1)(degreeV + 1) points (X, Y, ·, W), i along u, as screenSpacePatch
// gives them (the projection is (X/W, Y/W) in pixels; the third coordinate is ignored).
// Returns (uu, uv, vv) such that every triangle of a uniform grid with legs h = 1/N_u,
// k = 1/N_v deviates at most (h²·uu + 2hk·uv + k²·vv)/8 pixels from the image at the same
// (u, v) (affine interpolation on screen); divisionsFromBounds turns them into counts. These
// play the role of Filip's sup‖S''‖ but are not bounds of S'' itself. `bounded` is false when
// some W ≤ 0 (the control net reaches the eye plane: use viewDivisions). degreeV may be 0
// (a curve: uv = vv = 0).
SecondDerivativeBounds projectedGridBounds(const glm::dvec4* net, int degreeU, int degreeV);

// Counts of a uniform grid whose *estimated* screen-space deviation is ≤ tolerance pixels: not
// a bound (docs/realtime.md, "Counts": its margin is measured). Per coefficient of the net, the
// quotient rule gives a triple (S_uu, S_uv, S_vv) of the image's second partials from the
// coefficients of P, w and their derivatives (exact at the corners; in the affine limit the
// Bernstein coefficients of S'', whose hull holds it everywhere), once as the affine
// interpolation's error sees S'' and once as the perspective-correct one does. Under a
// constant second derivative H the deviation of a triangle is exactly ½·max over it of
// Σ λ_i λ_j ‖e_ijᵀ H e_ij‖ (the directional method's constant part, division/directional.cpp);
// the estimate is its largest value over the triples for the grid's legs (1/N_u, 0), (0, 1/N_v)
// and both diagonals. The counts: each direction's own need, both scaled until the estimate
// passes, rounded up, then the neighbouring grids of smaller product that still pass. What it
// leaves out: how S'' varies within a triangle and between the coefficients, small where
// triangles are small on screen. Degrees 1..3 (degreeV 0: a curve, counted as Filip's
// ‖C''‖·h²/8 on its coefficients); status Unbounded when some W ≤ 0, Capped when a count
// exceeds maxPerDirection.
// `sideSegments` (sides V0, U1, V1, U0 as in the stitched pattern, or null): the edge counts
// the patch's strips will join; a side whose count is below the inner grid's along it raises
// the count across it until its strips pass the estimate too.
Divisions estimatedProjectedDivisions(const glm::dvec4* net, int degreeU, int degreeV,
                                      double tolerance, int maxPerDirection,
                                      const std::array<int, 4>* sideSegments = nullptr);

}  // namespace tessera
