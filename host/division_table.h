// The comparison of paper 002 (Kawasaki et al., table 1), reproduced: rational surfaces with
// zero weights (quarter cylinders, torus patches seen from viewpoints on a control point's
// plane; rational_samples.h), and for each the division number N_u·N_v of
//   (i) the split method, (ii)/(iii) Abi-Ezzi with zero weights replaced by 0.001 / 0.01,
//   (iv) the true value: the smallest uniform N_u·N_v whose measured deviation is ≤ TOL,
//   (v) beyond the paper: the subdivided bound, (vi) the cell-wise bound, (vii) the
//   directional bound,
// all in pixels of the camera's viewport. Over-division ratio = average division number over
// the average of (iv), as the paper computes it (3630.57 / 735.14 = 4.939).
#pragma once
#include <string>
#include <vector>

#include "rational_samples.h"

namespace tessera {

struct DivisionTableOptions {
  // TOL 2 px on a 256² viewport (the same counts as 8 px on 1024²): the eye sits at a control
  // point, so the near parts of the patches are huge on screen, and the true value is found by
  // measuring grids, whose cost grows with the division number.
  double tolerance = 2.0;  // pixels
  int viewport = 256;      // square, pixels; 90° field of view
  bool full = false;       // more surfaces and viewpoints (zeroWeightViews(full))
};

struct DivisionViewRow {
  std::string name;
  long long split = 0, sub001 = 0, sub01 = 0, truth = 0, subdivided = 0, cellwise = 0,
            directional = 0;
  // measured, px
  double splitDeviation = 0, subdividedDeviation = 0, cellwiseDeviation = 0,
         directionalDeviation = 0;
};

struct DivisionTable {
  std::vector<DivisionViewRow> views;
  double tolerance = 0;
  int viewport = 0;
  // Averages over the views, in the order split, 0.001, 0.01, subdivided, cellwise,
  // directional, truth.
  double average[7] = {0, 0, 0, 0, 0, 0, 0};
  double worstSubdividedRatio = 0;  // max over views of subdivided / truth
  double worstCellwiseRatio = 0;    // max over views of cellwise / truth
  double worstDirectionalRatio = 0;  // max over views of directional / truth
  // max over views of the split, subdivided, cellwise and directional grids' deviations
  double worstDeviation = 0;
  double subdividedSeconds = 0, cellwiseSeconds = 0, directionalSeconds = 0;  // all views
};

DivisionTable divisionComparison(const DivisionTableOptions& options);

// The paper's layout (method, average division number, over-division ratio), then the
// per-view rows when `perView`.
std::string formatDivisionTable(const DivisionTable& table, bool perView);

}  // namespace tessera
