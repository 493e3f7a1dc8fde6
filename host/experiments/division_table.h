// The comparison of paper 002 (Kawasaki et al., table 1), reproduced: rational surfaces with
// zero weights (quarter cylinders, torus patches seen from viewpoints on a control point's
// plane; rational_samples.h), and for each the division number N_u·N_v of
//   (i) the split method, (ii)/(iii) Abi-Ezzi with zero weights replaced by 0.001 / 0.01,
//   beyond the paper: the subdivided, cell-wise, directional and direct bounds,
//   and the true value: the smallest uniform N_u·N_v whose measured deviation is ≤ TOL,
// all in pixels of the camera's viewport. Over-division ratio = average division number over
// the average true value, as the paper computes it (3630.57 / 735.14 = 4.939).
#pragma once
#include <string>
#include <vector>

#include "experiments/rational_samples.h"

namespace tessera {

struct DivisionTableOptions {
  // TOL 2 px on a 256² viewport (the same counts as 8 px on 1024²): the eye sits at a control
  // point, so the near parts of the patches are huge on screen, and the true value is found by
  // measuring grids, whose cost grows with the division number.
  double tolerance = 2.0;  // pixels
  int viewport = 256;      // square, pixels; 90° field of view
  bool full = false;       // more surfaces and viewpoints (zeroWeightViews(full))
};

// The table's columns, in the order printed.
enum DivisionColumn {
  kSplitColumn,
  kWeight0001Column,  // zero weights replaced by 0.001
  kWeight001Column,   // zero weights replaced by 0.01
  kSubdividedColumn,
  kCellwiseColumn,
  kDirectionalColumn,
  kDirectColumn,
  kTruthColumn,
  kDivisionColumns
};
// The columns whose grids must pass: the bounds (the substitutions are not bounds).
constexpr DivisionColumn kBoundColumns[] = {kSplitColumn, kSubdividedColumn, kCellwiseColumn,
                                            kDirectionalColumn, kDirectColumn};
const char* divisionColumnName(DivisionColumn column);

struct DivisionViewRow {
  std::string name;
  long long faces[kDivisionColumns] = {};
  // Measured deviation (px) of each bound column's grid.
  double deviation[kDivisionColumns] = {};
};

struct DivisionTable {
  std::vector<DivisionViewRow> views;
  double tolerance = 0;
  int viewport = 0;
  double average[kDivisionColumns] = {};    // division number over the views
  double worstRatio[kDivisionColumns] = {};  // max over views of faces / true faces
  double seconds[kDivisionColumns] = {};     // time in each method, all views
  double worstDeviation = 0;  // max over views and bound columns of the measured deviation
  double ratio(DivisionColumn column) const { return average[column] / average[kTruthColumn]; }
};

DivisionTable divisionComparison(const DivisionTableOptions& options);

// The paper's layout (method, average division number, over-division ratio), then the
// per-view rows when `perView`.
std::string formatDivisionTable(const DivisionTable& table, bool perView);

}  // namespace tessera
