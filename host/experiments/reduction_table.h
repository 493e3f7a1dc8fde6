// The control-point reduction paper's table (Hayashimoto et al., Table 1): per threshold,
// curvature-chosen against randomly chosen knots — compression ratio (eq. 3), and what the
// paper only saw in pictures, a waviness number — plus the errors and which limit stopped
// each pass. `tessera reduce` prints it; docs/reduction.md records the large surface's.
#pragma once
#include <string>
#include <vector>

#include "reduction/curve_product.h"
#include "reduction/knot_removal.h"

namespace tessera {

// Total variation of curvature along iso-curves, averaged: for `isoCurves` iso-parameter
// lines in each direction, Σ_k |κ(t_{k+1}) − κ(t_k)| over `samples` + 1 evenly spaced
// parameters, κ = |S_t × S_tt| / |S_t|³ (0 where S_t vanishes). This is ∫|dκ/ds| ds, in 1/mm:
// undulations add to it, a faithful reduction keeps it close to the original's.
double waviness(const BSplineSurface& surface, int isoCurves = 48, int samples = 400);

struct ReductionTableRow {
  double threshold = 0.0;
  KnotChoice choice = KnotChoice::Curvature;
  ReductionResult result;  // its surface is kept for writing
  double waviness = 0.0;
  double seconds = 0.0;
};

// Reduces `surface` for every threshold with each knot choice (base supplies the rest of the
// options, e.g. progress); `product` null = CPU only.
std::vector<ReductionTableRow> reductionTable(
    const BSplineSurface& surface, const std::vector<double>& thresholds,
    const ReductionOptions& base, CurveProduct* product,
    const std::vector<KnotChoice>& choices = {KnotChoice::Curvature, KnotChoice::Random});

// The table as text, with the original's waviness for reference.
std::string formatReductionTable(const std::vector<ReductionTableRow>& rows,
                                 double originalWaviness);

}  // namespace tessera
