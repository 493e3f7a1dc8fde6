// The asymptotic lower bound on the triangles of any interpolating mesh within δ of a surface
// (issue 15, "know how far from optimal we are"; derivation and constants: docs/lower_bound.md):
//   N_min(δ) = (1/δ) · [ w₊ ∫_{K>0} √K dA + w₋ ∫_{K<0} √−K dA ],
//   w₊ = 2/(3√3) (equilateral triangles in the Hessian metric), w₋ = 1/(2√5) (saddles).
// √|K| dA = √|LN − M²| du dv with L, M, N the second derivatives dotted with the unit normal,
// integrated by Gauss–Legendre on k×k cells per patch, k doubled until the result settles.
// Double precision; polynomial and rational patches of any degree (patchDerivatives).
#pragma once
#include <vector>

#include "geometry/patch.h"

namespace tessera {

// Triangles per unit of ∫√|K| dA at δ = 1 (docs/lower_bound.md derives both; the issue's
// 0.3849 and 0.2236 are these rounded to four digits).
constexpr double kEllipticTriangleDensity = 0.38490017945975050;    // 2/(3√3)
constexpr double kHyperbolicTriangleDensity = 0.22360679774997897;  // 1/(2√5)

// ∫∫ √|K| dA split by the sign of K (parabolic points, K = 0, add nothing).
struct CurvatureRootIntegral {
  double positive = 0.0;  // ∫_{K>0} √K dA
  double negative = 0.0;  // ∫_{K<0} √−K dA
};

// Over one patch: `cells`×`cells` equal cells in (u, v), an n-point Gauss–Legendre rule
// (n = `points`, 1..32) along each direction of each cell. Gauss points are interior, so a
// collapsed edge (a pole) is never evaluated; the integrand √|LN − M²| is bounded anyway
// (≤ |Suu||Svv| + |Suv|² for a unit normal), so it stays finite near one.
CurvatureRootIntegral integrateCurvatureRoot(const BezierPatch& patch, int cells, int points);

struct LowerBoundOptions {
  int points = 4;                 // Gauss–Legendre points per direction per cell
  int maxCells = 64;              // the largest k tried (cells per direction)
  double relativeChange = 1e-3;   // stop when |N_k − N_{k/2}| ≤ this · N_k
  unsigned threads = 0;           // patches in parallel on this many threads, 0: all
};

struct LowerBoundStep {
  int cells = 0;                  // k
  CurvatureRootIntegral integral; // over all patches at this k
  double triangles = 0.0;         // N_min at this k
};

struct TriangleLowerBound {
  double tolerance = 0.0;   // δ, model units
  double triangles = 0.0;   // N_min(δ) = positive + negative
  double positive = 0.0;    // w₊ ∫_{K>0} √K dA / δ
  double negative = 0.0;    // w₋ ∫_{K<0} √−K dA / δ
  CurvatureRootIntegral integral;  // the last step's integrals (independent of δ)
  int cells = 0;            // k of the last step
  bool converged = false;   // the last relative change was within LowerBoundOptions::relativeChange
  std::vector<LowerBoundStep> refinement;  // k = 1, 2, 4, … in order
  double ms = 0.0;          // time the integration took
};

// N_min from integrals already computed (no re-integration for another δ).
double lowerBoundTriangles(const CurvatureRootIntegral& integral, double tolerance);

// The bound for `patches` at `tolerance` δ > 0 (model units). Throws std::invalid_argument
// for δ not finite and positive, bad options or an invalid patch.
TriangleLowerBound asymptoticTriangleLowerBound(const std::vector<BezierPatch>& patches,
                                                double tolerance,
                                                const LowerBoundOptions& options = {});

}  // namespace tessera
