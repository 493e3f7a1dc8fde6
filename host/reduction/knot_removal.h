// Control-point reduction of B-spline surfaces by the inverse Oslo algorithm
// (Hayashimoto, Fukui, Mitani, Nishihara: "Method of reducing B-spline surface control points
// for considering curvature", §3). This header holds the method's definitions and its
// specification: the SVD pseudo-inverse, applied as-is (small inputs only). The fast path
// that makes the same decisions at scale is reduction_fast.h; docs/reduction.md explains both.
//
// The method, as implemented here:
// - Knots x ⊂ y (y the original knots of one direction): the Oslo matrix A (R = A·Q, oslo.h)
//   has full column rank, and Q = A⁺·R is the least-squares fit of the original control
//   points R, measured on the original (fine) control net.
// - A surface is reduced one direction at a time. Every curve of that direction (every row of
//   the net) shares x and y, so one A⁺ serves them all: one matrix product per direction.
// - Knots are tried one at a time, chosen by curvature (KnotChoice::Curvature: the least
//   bending removal, re-ranked after each removal; CurvatureFixed: a fixed order by increasing
//   curvature of the original surface's curves at the knot), or in a seeded random order
//   (KnotChoice::Random); reduction_order.h. After each removal the reduced surface is compared with the original;
//   a removal that would take the error above the pass's target is undone, that knot is kept,
//   and the next knot is tried. The pass ends when every knot has been tried.
//   (Stopping at the first refusal, the paper's literal flow, starves the curvature order: its
//   lowest-curvature knots lie side by side, so it empties one flat stretch, exceeds the target
//   there and stops while isolated knots elsewhere were still free; docs/reduction.md.)
// - Error = the difference surface, refined onto the original knots: its control points
//   d_ij = (reduced refined) − (original). mean = mean_ij |d_ij| (the paper's 誤差の平均),
//   max = max_ij |d_ij|, which bounds the true largest deviation (convex hull property).
#pragma once
#include <Eigen/Dense>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "bspline/bspline.h"
#include "bspline/oslo.h"

namespace tessera {

// --- Specification pieces ----------------------------------------------------------------
// The Moore–Penrose pseudo-inverse by SVD; singular values at or below
// max(rows, cols)·ε·σ_max are treated as zero (they never occur for Oslo matrices).
Eigen::MatrixXd pseudoInverse(const Eigen::MatrixXd& a);

// Inverse Oslo for one curve: the control points on coarseKnots ⊂ fineKnots closest (least
// squares over the fine control points) to fineCp, Q = A⁺·R. Throws std::invalid_argument
// (naming the reason) for invalid knot vectors, a coarse vector that is not contained in the
// fine one, a wrong number of control points or non-finite control points.
std::vector<glm::dvec3> inverseOslo(int degree, const std::vector<double>& coarseKnots,
                                    const std::vector<double>& fineKnots,
                                    const std::vector<glm::dvec3>& fineCp);

// --- Options and results -----------------------------------------------------------------
// Curvature (default): the knot whose removal bends least, re-ranked after every removal —
// score = the largest κ·|C′|² of the curves (their normal acceleration, κ in the curve's own
// parameter) over the span the removal would create, × that span's length h². κ·(|C′|h)²/8 is
// the sagitta of an arc of curvature κ and length |C′|h: the local error a removal risks. So
// flat knots still go first, but a knot whose neighbours are already gone waits (reduction_order.h).
// CurvatureFixed: the paper's literal order, by increasing κ on the original surface, fixed
// before the pass (it empties flat stretches first; docs/reduction.md measures both).
// CurvatureSweeps: the fixed order in sweeps that skip (defer to the next sweep) a knot whose
// removal would open a span containing a knot removed in the same sweep — spreading without
// a span-aware score, measured against it in docs/reduction.md.
// Random: a seeded random order, the paper's comparison.
enum class KnotChoice { Curvature, CurvatureFixed, CurvatureSweeps, Random };
const char* knotChoiceName(KnotChoice choice);
// How the curvatures of all curves of a direction at one knot are combined into its score.
// Max (default): a knot is as curved as its most curved curve, so a feature crossing only a
// few rows still protects its knots. Mean: the average over the rows.
enum class CurvatureAggregate { Max, Mean };
// Which error a pass keeps under its target: Mean (the paper) or Max (the control-net bound).
enum class ErrorMeasure { Mean, Max };
enum class StopReason {
  Threshold,             // at least one removal would have exceeded the target: those were undone
  MinimumControlPoints,  // no interior knot left: degree + 1 control points in this direction
};
const char* stopReasonName(StopReason reason);
const char* directionName(ParamDirection direction);

struct ReductionProgress {
  int pass = 0;  // 0 or 1
  ParamDirection direction = ParamDirection::V;
  int removed = 0;     // knots removed so far in this pass
  int tried = 0;       // knots tried so far (removed or refused)
  int removable = 0;   // interior knots this pass could remove
  double error = 0.0;  // the measured error (ReductionOptions::measure) of the last attempt
  double target = 0.0;
};

struct ReductionOptions {
  double threshold = 0.01;  // model units; finite and ≥ 0
  ErrorMeasure measure = ErrorMeasure::Mean;
  KnotChoice choice = KnotChoice::Curvature;
  CurvatureAggregate aggregate = CurvatureAggregate::Max;
  uint64_t seed = 1;  // KnotChoice::Random
  // The first pass may use this share of the threshold; the second continues up to the whole
  // threshold (both measured against the original). 1 would leave the second pass nothing.
  double firstPassShare = 0.5;
  ParamDirection firstDirection = ParamDirection::V;
  // Fast path only (reduction_fast.h): the smallest half-width, in coarse control points, of
  // the window re-solved after a removal, and the change at its edge (× the data's largest
  // coordinate) below which the rest of the curve is taken as unchanged.
  int minWindow = 8;
  double windowTolerance = 1e-11;
  int threads = 0;  // fast path: worker threads, 0 = one per hardware thread
  std::function<void(const ReductionProgress&)> progress;  // called after every attempt
};

struct DeviationStats {
  double mean = 0.0;
  double max = 0.0;
  double value(ErrorMeasure m) const { return m == ErrorMeasure::Mean ? mean : max; }
};

struct PassReport {
  ParamDirection direction = ParamDirection::V;
  int originalCount = 0;  // control points along this direction before the pass
  int keptCount = 0;      // and after
  int removed = 0;
  int refused = 0;  // knots whose removal would have exceeded the target (kept)
  StopReason stop = StopReason::MinimumControlPoints;
  double target = 0.0;
  DeviationStats error;        // after the pass, against the original surface
  // The smallest measured error among the refused removals, each measured when it was tried
  // (Threshold only; > target by construction).
  double refusedError = 0.0;
  double seconds = 0.0;
};

struct ReductionResult {
  BSplineSurface surface;
  PassReport passes[2];
  DeviationStats error;  // final, against the original
  long long originalControlPoints = 0;
  long long keptControlPoints = 0;
  double compressionPercent() const {
    return originalControlPoints == 0 ? 0.0 : 100.0 * keptControlPoints / originalControlPoints;
  }
};

// Throws std::invalid_argument unless the threshold is finite and ≥ 0, the share in (0, 1],
// the window settings positive.
void validateReductionOptions(const ReductionOptions& options);

// Validates the surface (knots, counts) and that every control point is finite.
void validateSurfaceForReduction(const BSplineSurface& surface);

// Books one attempt of a pass (removed, or refused at `measured` > target) in `report` and calls
// options.progress: the bookkeeping both implementations share.
void recordAttempt(PassReport& report, int pass, int removable, bool removed, double measured,
                   const ReductionOptions& options);

// --- Knot order -----------------------------------------------------------------------------
// Curvature κ = |C′×C″|/|C′|³ of every curve of `direction` (the curves whose control points
// are the rows of the net along it) at every knot of that direction, combined over the curves
// by `aggregate`; 0 where C′ vanishes. One entry per knot index; only interior knots
// (degree < index < count) are meaningful, the others are 0.
std::vector<double> knotCurvature(const BSplineSurface& surface, ParamDirection direction,
                                  CurvatureAggregate aggregate);

// Like knotCurvature, but κ·|C′|² = |C′×C″|/|C′| (the normal acceleration): the curvature in
// the curves' own parameter, which KnotChoice::Curvature multiplies by a squared knot span.
std::vector<double> knotBending(const BSplineSurface& surface, ParamDirection direction,
                                CurvatureAggregate aggregate);

// The fixed orders: the interior knot indices of `direction` by increasing knotCurvature (ties
// by index; CurvatureFixed, and the ranking CurvatureSweeps walks), or for Random a
// Fisher–Yates shuffle with mt19937_64 seeded by seed (u) or seed + 1 (v). KnotChoice::Curvature
// is re-ranked as knots go (KnotSchedule, reduction_order.h); here it gives the fixed sort.
std::vector<int> removalOrder(const BSplineSurface& surface, ParamDirection direction,
                              const ReductionOptions& options);

// --- Measuring ------------------------------------------------------------------------------
// Mean and max of |d_ij| over the original's control net, d = reduced refined onto the
// original's knots − original. Throws std::invalid_argument unless the reduced surface has
// the same degrees and knot vectors contained in the original's.
DeviationStats netDeviation(const BSplineSurface& original, const BSplineSurface& reduced);

// --- The specification ----------------------------------------------------------------------
// The whole method with A⁺ by SVD recomputed after every removal and the error by refining the
// whole candidate: O(removals · n³). For tests and small surfaces only.
ReductionResult reduceSurfaceReference(const BSplineSurface& surface,
                                       const ReductionOptions& options);

}  // namespace tessera
