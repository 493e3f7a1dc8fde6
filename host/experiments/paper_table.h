// The quad-tree paper's experiment (Moriyama & Harada, tables 1-3), extended: for each split
// rule and threshold, depth and leaves as the paper reports, plus triangles, the measured
// maximum deviation from the true surface, and the uniform grid (rule A) that reaches the same
// deviation — so methods are compared on accuracy per triangle, not on leaves alone.
#pragma once
#include <string>
#include <vector>

#include "mesh/tessellate.h"

namespace tessera {

struct PaperTableRow {
  char method = 'B';
  float threshold = 0;
  uint32_t depth = 0;
  size_t leaves = 0;
  size_t triangles = 0;
  double maxDeviation = 0;
  int uniformN = 0;               // smallest N whose N×N grid per patch deviates no more
  size_t uniformTriangles = 0;    // its triangle count
  double uniformDeviation = 0;
};

// Rows for methods B, C, D at each threshold (linearity = flatness = threshold).
std::vector<PaperTableRow> paperTable(const std::vector<BezierPatch>& patches,
                                      const std::vector<float>& thresholds, Backend& backend);

std::string formatPaperTable(const std::string& title, const std::vector<PaperTableRow>& rows);

}  // namespace tessera
