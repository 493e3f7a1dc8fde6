// One pass of the fast reduction (reduction_fast.h): the curves of one direction, their
// original knots, and the least-squares fit kept up to date by window solves as knots are
// removed. Internal to reduction_fast.cpp; a header of its own so that each file keeps to one
// job.
#pragma once
#include <vector>

#include "reduction/banded_oslo.h"
#include "reduction/knot_removal.h"
#include "reduction/fast.h"

namespace tessera {

// The error of fine slabs of a candidate against the original surface. A slab is every
// original control point with one fine index j in the pass's direction; `others` of them.
// A candidate slab arrives as P_j = (A·Q)_j: K = 3·(points per curve row) doubles. In the
// first pass those points are the original's own positions (refine == null, others = K/3);
// in the second they are still coarse in the other direction and `refine` (that direction's
// Oslo matrix) takes them to the original's knots first.
struct SlabError {
  const double* original = nullptr;  // slab j, point o: original[(j·others + o)·3 + xyz]
  int others = 0;
  const BandMatrix* refine = nullptr;

  // sum[j − ja] = Σ_o |d_jo|, max[j − ja] = max_o |d_jo| for the slabs ja ≤ j < jb, whose
  // candidate rows are p[(j − ja)·columns ...].
  void measure(int ja, int jb, const double* p, int columns, double* sum, double* max) const;
};

class ReductionPass {
 public:
  // data: the pass's least-squares data, m × columns row-major (fine index major), m the
  // number of control points for `fineKnots`. Starts with every knot present (Q = data).
  ReductionPass(int degree, const std::vector<double>& fineKnots, const double* data,
                int columns, const SlabError& error, const ReductionOptions& options,
                FastPathStats& stats);

  DeviationStats error() const;
  const std::vector<double>& knots() const { return x_; }
  int controlCount() const { return static_cast<int>(qRow_.size()); }
  // The fit as kept by the window solves, n × columns.
  std::vector<double> net() const;

  // Removes fine knot `knot` (an interior index into fineKnots, still present) unless the error
  // (`measure`) would then exceed `target`. Returns whether it was removed; `measured` gets
  // the error with the knot removed either way.
  bool tryRemove(int knot, ErrorMeasure measure, double target, double* measured);

 public:
  // How a window solve moved the held-fixed neighbourhood: the largest change at the window's
  // outermost columns (edge), and how many columns wider (> 0) or narrower (< 0) the window
  // should have been for that change to be at the tolerance, from the decay between the edge
  // and a column p + 1 further in (the change decays about geometrically there).
  struct WindowChange {
    double edge = 0.0;
    int resize = 0;
  };

 private:
  // Solves the window [a, b] of the candidate knots xNew_ (fine rows ja ≤ j < jb), leaving
  // the window's rows of Q in z_ and the fine rows (A·Q)_j in pRows_.
  WindowChange solveWindow(int pos, int a, int b, int ja, int jb);

  int p_, m_, columns_;
  const std::vector<double>& y_;
  const double* data_;
  const SlabError& error_;
  FastPathStats& stats_;
  double tolerance_;
  int minWindow_, window_, threads_;
  double pointCount_;

  std::vector<double> x_;          // current knots
  std::vector<int> fineIndex_;     // x_[k] is fineKnots[fineIndex_[k]]
  std::vector<double> pool_;       // storage of the coarse rows of Q
  std::vector<double*> qRow_;      // Q's row i, columns_ doubles
  std::vector<double> slabSum_, slabMax_;
  double total_ = 0.0;

  // Scratch of one removal.
  std::vector<double> xNew_, rowValues_, g_, z_, pRows_, newSum_, newMax_;
  std::vector<int> rowFirst_;
  std::vector<std::vector<double>> residual_;  // per thread
};

}  // namespace tessera
