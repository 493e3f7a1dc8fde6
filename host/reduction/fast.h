// The fast path of the control-point reduction (knot_removal.h has the method and its SVD
// specification). Same knot order, same error, same stopping rule, so the same decisions; what
// changes is how the least-squares fit Q = A⁺R is kept up to date after each removal:
//
// - A is kept in band form (banded_oslo.h). Removing one knot changes p + 2 columns of A into
//   p + 1; the exact new fit differs from the old one everywhere, but the difference decays
//   exponentially away from the knot (the inverse of a B-spline normal matrix does). So only a
//   window of coarse control points around the knot is re-solved (banded normal equations, the
//   rest held fixed), and the window is doubled until the change at its edges is below
//   windowTolerance × the data's largest coordinate.
// - Only the fine control points whose rows touch the window change, so the error is updated
//   slab by slab (a slab = all original points with one fine index in the pass's direction).
// - At the end of each pass the net is recomputed from scratch: the banded solve on the CPU,
//   or A⁺ (pseudoInverseBand) applied to all curves in one product on a CurveProduct backend
//   (the GPU). The reported errors are measured on that final net.
#pragma once
#include "reduction/curve_product.h"
#include "reduction/knot_removal.h"

namespace tessera {

struct FastPathStats {
  long long windowSolves = 0;   // window solves, retries included
  long long windowRetries = 0;  // solves repeated with a doubled window
  int widestWindow = 0;         // in coarse control points
  long long slabsMeasured = 0;  // fine slabs whose error was recomputed, over all removals
  // Per pass: the largest coordinate difference between the net kept by window updates and
  // the from-scratch banded solve at the end of the pass (the drift of the local updates).
  double drift[2] = {0.0, 0.0};
  double searchSeconds[2] = {0.0, 0.0};   // the removal loop
  double productSeconds[2] = {0.0, 0.0};  // the final net (banded solve or A⁺ product)
};

// Same contract as reduceSurfaceReference. `product`: null computes the final net of each
// pass by the banded solve in double; otherwise A⁺ is formed and applied by `product` (its
// precision, e.g. fp32 on the GPU, then carries into the second pass and the result).
ReductionResult reduceSurface(const BSplineSurface& surface, const ReductionOptions& options,
                              CurveProduct* product = nullptr, FastPathStats* stats = nullptr);

}  // namespace tessera
