// Division counts for rational Bézier curves and patches: how many uniform segments per
// direction keep the chordal deviation of the polyline / triangle grid within TOL (rule A of
// the quad-tree paper with a computed grid). Source: Kawasaki, Sakaibara, Kuwana, "Division
// method to evade singular points for free curves and surfaces" (paper 002), which extends the
// bound of Filip et al. (1986) and Abi-Ezzi (1989) to zero weights. The derivation, the slips
// in the printed A_ijk and why the printed B1..B8 is not a bound in general:
// docs/rational_division.md.
//
// Deviation is parametric: a point of a segment (triangle) against the curve (surface) at the
// same mix of parameters, the quantity Filip's bound controls and host/mesh/deviation.h measures.
// Filip: on a triangle with legs h (u) and k (v) it is at most
//   (h²·M_uu + 2hk·M_uv + k²·M_vv) / 8,   M = sup of ‖S_uu‖, ‖S_uv‖, ‖S_vv‖,
// so N_u×N_v cells (each split into two triangles) are enough when
//   M_uu/N_u² + 2·M_uv/(N_u·N_v) + M_vv/N_v² ≤ 8·TOL.
// The methods differ only in how they bound M.
#pragma once
#include <glm/glm.hpp>

#include <limits>
#include <string>

#include "geometry/patch.h"

namespace tessera {

enum class DivisionMethod {
  // max ‖A_ijk‖ / (w_i w_j w_k) over all index triples (Filip; Abi-Ezzi, eq. 3.1 with the
  // corrected A_ijk). Every weight non-zero and of one sign, else std::invalid_argument.
  AbiEzzi,
  // B1..B8 exactly as printed (eq. 4.1–4.2): a vanished denominator is replaced by the
  // smallest non-zero weight. Weights ≥ 0. Not a bound in general (it under-estimates when
  // zero weights carry more than half the basis mass somewhere); kept for the comparison.
  PaperSplit,
  // B1..B8 with the vanished-denominator factor bounded: the 1/min w of the paper becomes
  // ρ ≥ sup β/|w| (β: the basis mass of the vanished weights) and, for negative weights,
  // σ ≥ sup ω/|w| (ω = Σ|w_l|B_l over the others), both from q×q de Casteljau pieces.
  // Any signs, as long as w ≠ 0 on the patch. The GPU runs this one.
  Split,
  // Beyond the paper: de Casteljau pieces refined where the bound is loose; on each piece the
  // exact Bernstein coefficients of the numerator of S'' over those of w³.
  Subdivided,
  // Beyond the paper: Filip's inequality per cell of the uniform grid, with the second
  // derivatives bounded over that cell only (the numerators of Subdivided restricted to it);
  // the smallest grid found below the Subdivided counts whose every cell passes.
  CellWise,
  // Beyond the paper: CellWise, where a cell also passes when the directional bound of its
  // deviation is within TOL: the exact error of the cell's constant second derivative along
  // the triangles' three edge directions, plus Filip's bound of how far S'' strays from that
  // constant over the cell (host/division/detail/directional.h). Surfaces; a curve gets CellWise.
  Directional,
  // Beyond the paper: CellWise, where a cell also passes when the deviation itself is proven
  // within TOL: e = E/w with the polynomial E = w·L − P (L the triangle's linear interpolant),
  // bounded by the hull of its Bernstein coefficients over w's on squares cut until the bound
  // passes or a corner fails (host/division/detail/direct.h). Tends to the true sup; surfaces only, a
  // curve gets CellWise.
  Direct,
};

const char* divisionMethodName(DivisionMethod method);
// "abi-ezzi", "paper", "split", "subdivided", "cellwise", "directional", "direct";
// throws std::invalid_argument otherwise.
DivisionMethod parseDivisionMethod(const std::string& name);

enum class DivisionStatus {
  Ok,
  Capped,     // a count exceeded maxPerDirection and was clamped to it
  Unbounded,  // w reaches zero on the patch (its image runs off to infinity): counts clamped
  Culled,     // view-dependent: nothing of the patch is visible (behind the eye): counts 0
};
const char* divisionStatusName(DivisionStatus status);

// A visible region in screen-space homogeneous coordinates (X, Y, ·, W): 0 ≤ X ≤ W·width,
// 0 ≤ Y ≤ W·height, W ≥ nearW. Subdivided drops pieces whose control points all lie outside
// one of these half-spaces (convex hull), so triangles that the rasterizer clips do not drive
// the count; the other methods ignore it.
struct ClipRegion {
  bool enabled = false;
  double width = 0, height = 0, nearW = 0;
};

struct DivisionOptions {
  double tolerance = 0.5;  // largest chordal deviation (model units, or pixels in view mode)
  DivisionMethod method = DivisionMethod::Split;
  int maxPerDirection = 1024;  // counts above this are clamped (status Capped)
  // Split: q, the pieces per direction on which sup β/|w| and sup ω/|w| are bounded.
  int ratioPieces = 4;
  // Split: weights with |w| ≤ this · max|w| join the vanished class (0: exact zeros only, as
  // in the paper). Valid for any value; a small positive one keeps near-zero weights (a
  // control point next to the eye plane) from blowing up the 1/(w_i w_j w_k) terms.
  double zeroClassThreshold = 0.0;
  // Subdivided: refine until every relevant bound is within this fraction of the largest
  // sampled value, or the budget below runs out.
  double refineSlack = 0.05;
  int maxPieces = 4096;
  int maxDepth = 14;
  // CellWise: a cell whose own bound fails is bounded as the maximum over its 2×2 sub-cells,
  // this many levels deep.
  int cellRefinement = 2;
  // Direct: the most times a square of a cell is cut in four before the cell counts as failed.
  int directDepth = 6;
  ClipRegion clip;
};

// Upper bounds of sup‖S_uu‖, sup‖S_uv‖, sup‖S_vv‖ over the patch (for a curve: uu only).
struct SecondDerivativeBounds {
  double uu = 0, uv = 0, vv = 0;
  bool bounded = true;  // false: w reaches zero (or changes sign) on the patch
  bool visible = true;  // false: Subdivided with a ClipRegion found every piece clipped
  int pieces = 1;       // pieces the bound was taken over
};

struct Divisions {
  int nu = 1, nv = 1;               // uniform cells along u and v
  double realU = 1.0, realV = 1.0;  // the real-valued counts before rounding up
  SecondDerivativeBounds bounds;
  DivisionStatus status = DivisionStatus::Ok;
  // The paper's "division number": faces of the N_u×N_v grid.
  long long divisionNumber() const { return static_cast<long long>(nu) * nv; }
};

// Throws std::invalid_argument for a degree outside 1..7, a wrong control-point count, a
// non-finite coordinate, every weight zero, or weights the method does not accept.
void validateDivisionInput(const RationalBezierCurve& curve, DivisionMethod method);
void validateDivisionInput(const RationalBezierPatch& patch, DivisionMethod method);

// A_ijk of c'' = Σ A_ijk B_i B_j B_k / Σ w_i w_j w_k B_i B_j B_k for a curve of degree K, as
// derived in docs/rational_division.md: with D1_l = (K−l)ΔH_l + l∇H_l and
// D2_l = (K−l)(K−l−1)Δ²H_l + 2l(K−l)Δ²H_(l−1) + l(l−1)Δ²H_(l−2) (homogeneous H = (P, w)),
//   A_ijk = (D2_i.P w_j − D2_i.w P_j) w_k − 2 (D1_i.P w_j − D1_i.w P_j) D1_k.w.
glm::dvec3 abiEzziCoefficient(const RationalBezierCurve& curve, int i, int j, int k);
// (3.2) as printed: (K−j−1) for (K−i−1), 2i(K−j) for 2i(K−i), and the last factor's index i
// for k. Only for the test that shows the slips matter.
glm::dvec3 abiEzziCoefficientAsPrinted(const RationalBezierCurve& curve, int i, int j, int k);

SecondDerivativeBounds secondDerivativeBounds(const RationalBezierPatch& patch,
                                              const DivisionOptions& options);
SecondDerivativeBounds secondDerivativeBounds(const RationalBezierCurve& curve,
                                              const DivisionOptions& options);

// The counts for given bounds: the real (N_u, N_v) ≥ 1 of smallest product meeting Filip's
// inequality (closed form, docs/rational_division.md), each rounded up, clamped to
// maxPerDirection. Unbounded bounds give maxPerDirection in both directions.
Divisions divisionsFromBounds(const SecondDerivativeBounds& bounds, double tolerance,
                              int maxPerDirection);

Divisions patchDivisions(const RationalBezierPatch& patch, const DivisionOptions& options);
Divisions curveDivisions(const RationalBezierCurve& curve, const DivisionOptions& options);

// The paper's alternative: every zero weight replaced by `value` (the numerator kept), after
// which AbiEzzi applies. The counts are then used for the original patch.
RationalBezierPatch substituteZeroWeights(const RationalBezierPatch& patch, double value);

}  // namespace tessera
