// Which knot a reduction pass tries next (knot_removal.h, KnotChoice). Shared by the SVD
// specification and the fast path, so both make the same choices.
//
// KnotChoice::Curvature re-ranks after every removal. The score of an untried knot k is
//   max over the original knots in (prev, next) of κ·|C′|²  ×  (y_next − y_prev)²,
// prev/next its present neighbours: the normal acceleration of the most bent curve over the
// span its removal would create (the knots already removed inside it included), times that
// span squared — proportional to the sagitta κ·L²/8 of that span (L = |C′|·h its arc length),
// i.e. the local error the removal risks. A fixed curvature order (the paper's literal rule,
// KnotChoice::CurvatureFixed) removes the flat knots side by side, opening long spans next to
// dense ones; here a knot's score grows as its neighbours go, so removals spread out and a
// flat stretch is thinned evenly before curved knots are touched. Ties go to the lower index.
//
// KnotChoice::CurvatureSweeps walks the fixed curvature order in sweeps; a knot whose removal
// would open a span containing a knot removed in the current sweep waits for the next sweep.
#pragma once
#include <set>
#include <utility>
#include <vector>

#include "reduction/knot_removal.h"

namespace tessera {

class KnotSchedule {
 public:
  KnotSchedule(const BSplineSurface& original, ParamDirection direction,
               const ReductionOptions& options);

  // The interior knot index (into the original knots of the direction) to try next, or −1
  // when every interior knot has been tried once.
  int next();
  // The outcome of trying `knot` (the one next() returned).
  void record(int knot, bool removed);
  // Interior knots of the direction: how many attempts the pass makes.
  int size() const { return count_; }

 private:
  double score(int knot) const;
  int nextInSweeps();

  int count_ = 0;
  KnotChoice choice_;
  // Fixed orders (CurvatureFixed, Random), and the order of the sweeps.
  std::vector<int> order_, deferred_;
  size_t at_ = 0;
  int sweep_ = 0;
  std::vector<int> removedInSweep_;  // per knot: the sweep that removed it, −1 if present
  // Re-ranked order (Curvature).
  std::vector<double> knots_, bending_, scoreOf_;
  std::vector<int> prev_, next_;  // present neighbours (the clamped end knots stay)
  std::set<std::pair<double, int>> queue_;  // untried knots by (score, index)
};

}  // namespace tessera
