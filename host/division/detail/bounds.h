// Net-level pieces of the division-count bounds (host/division/count.h), shared by the CPU
// reference, the subdivided bound and the tests. A curve is a net with m = 0.
#pragma once
#include <vector>

#include "division/count.h"
#include "geometry/homogeneous_net.h"

namespace tessera {

// Coefficients of the homogeneous partials in the net's own basis, bidegree (n, m): the
// degree-keeping derivative D_l = (n−l)(H_(l+1) − H_l) + l(H_l − H_(l−1)) along u or v
// (docs/rational_division.md, eq. D1), applied twice for the second partials.
struct DerivativeNets {
  std::vector<glm::dvec4> d1u, d1v, d2u, d2v, d11;
};
DerivativeNets derivativeNets(const HomogeneousNet& net);
std::vector<glm::dvec4> degreeKeepingDerivativeU(const std::vector<glm::dvec4>& h, int n, int m);
std::vector<glm::dvec4> degreeKeepingDerivativeV(const std::vector<glm::dvec4>& h, int n, int m);

// ρ ≥ sup β/|w| and σ ≥ sup ω/|w| over the patch, from the Bernstein coefficients of β, ω and
// w on q×q de Casteljau pieces (a ratio of two Bernstein polynomials with the denominator's
// coefficients all of one strict sign is at most the largest coefficient ratio).
// β = Σ_(l vanished) B_l, ω = Σ_(l not vanished) |w_l| B_l. bounded = false when some piece's
// w coefficients are not all of one strict sign, or two pieces disagree in sign.
struct WeightRatios {
  double rho = 0, sigma = 1;
  bool bounded = true;
  int sign = 1;  // the sign of w on the patch
};
WeightRatios vanishedWeightRatios(const HomogeneousNet& net, const std::vector<char>& vanished,
                                  int pieces);

// The B1..B8 class maxima for one second partial (0: uu, 1: uv, 2: vv, 3: uv with the roles
// of u and v exchanged in the numerator), indexed
// 4·[i vanished] + 2·[j vanished] + [k vanished]; the bound is Σ B_S σ^(3−|S|) ρ^|S|.
struct ClassMaxima {
  double b[8] = {0, 0, 0, 0, 0, 0, 0, 0};
};
ClassMaxima classMaxima(const HomogeneousNet& net, const DerivativeNets& d, int partial,
                        const std::vector<char>& vanished);
double combineClasses(const ClassMaxima& classes, double rho, double sigma);

// AbiEzzi, PaperSplit and Split (options.method).
SecondDerivativeBounds splitBounds(const HomogeneousNet& net, const DivisionOptions& options);
// Subdivided (host/division/subdivided.cpp); also the global bound CellWise starts from.
SecondDerivativeBounds subdividedBounds(const HomogeneousNet& net, const DivisionOptions& options);

// The exact Bernstein coefficients of the numerators of S_uu, S_uv, S_vv (S'' = N / w³) and of
// w³, all elevated to bidegree (3n, 3m) so that they pair coefficient by coefficient.
struct SecondDerivativeNumerators {
  VectorNet uu, uv, vv;
  ScalarNet w3;
};
SecondDerivativeNumerators secondDerivativeNumerators(const HomogeneousNet& net);

// The numerators restricted to [u0,u1]×[v0,v1] of the patch by de Casteljau. Their values
// stay derivatives in the patch's parameters. A curve's empty uv and vv nets stay empty, and
// a curve ignores v0, v1.
SecondDerivativeNumerators restrictNumerators(const SecondDerivativeNumerators& num, double u0,
                                              double u1, double v0, double v1);

// Bounds of sup‖S_uu‖, ‖S_uv‖, ‖S_vv‖ (in the patch's parameters) over a piece of parameter
// size hu×hv whose reparametrised numerators are `num`: max_k ‖N_k‖/|W_k| over h², hk, k².
// False (bounds untouched) unless W's coefficients are all of one strict sign.
bool numeratorRatioBounds(const SecondDerivativeNumerators& num, double hu, double hv,
                          double bounds[3]);

// True when every control point of `net` lies outside one half-space of the clip region (the
// convex hull does, so the piece is invisible). False when the clip is disabled.
bool outsideClip(const HomogeneousNet& net, const ClipRegion& clip);

// CellWise (host/division/cellwise.cpp): the smallest uniform grid found below the subdivided
// counts (`subdivided`, the grid of the global bound, which passes) whose every cell passes
// Filip's inequality with bounds over that cell only. Returns `subdivided` unless its status
// is Ok.
Divisions cellwiseDivisions(const HomogeneousNet& net, const DivisionOptions& options,
                            const Divisions& subdivided);

}  // namespace tessera
