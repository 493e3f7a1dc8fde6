#include "experiments/division_table.h"

#include <algorithm>
#include <cstdio>

#include "common/stopwatch.h"
#include "division/count.h"
#include "division/deviation.h"
#include "geometry/homogeneous_net.h"

namespace tessera {
namespace {

// Division numbers of the substitution alternative reach 10^10: no cap short of overflow.
constexpr int kUncapped = 1 << 30;

// The patch (screen space) each column's method runs on, and the method.
struct ColumnMethod {
  DivisionColumn column;
  DivisionMethod method;
  double zeroWeight;  // > 0: zero weights replaced by this first
};
constexpr ColumnMethod kMethods[] = {
    {kSplitColumn, DivisionMethod::Split, 0.0},
    {kWeight0001Column, DivisionMethod::AbiEzzi, 0.001},
    {kWeight001Column, DivisionMethod::AbiEzzi, 0.01},
    {kSubdividedColumn, DivisionMethod::Subdivided, 0.0},
    {kCellwiseColumn, DivisionMethod::CellWise, 0.0},
    {kDirectionalColumn, DivisionMethod::Directional, 0.0},
    {kDirectColumn, DivisionMethod::Direct, 0.0},
};

}  // namespace

const char* divisionColumnName(DivisionColumn column) {
  switch (column) {
    case kSplitColumn: return "split (this method)";
    case kWeight0001Column: return "weight 0 -> 0.001";
    case kWeight001Column: return "weight 0 -> 0.01";
    case kSubdividedColumn: return "subdivided (beyond)";
    case kCellwiseColumn: return "cellwise (beyond)";
    case kDirectionalColumn: return "directional (beyond)";
    case kDirectColumn: return "direct (beyond)";
    case kTruthColumn: return "true value";
    case kDivisionColumns: break;
  }
  return "?";
}

DivisionTable divisionComparison(const DivisionTableOptions& options) {
  DivisionTable table;
  table.tolerance = options.tolerance;
  table.viewport = options.viewport;
  const double tol = options.tolerance;
  for (const SampleView& view : zeroWeightViews(options.full, options.viewport, options.viewport)) {
    const RationalBezierPatch screen = screenSpacePatch(view.patch, view.camera);
    const HomogeneousNet net = toNet(screen);
    DivisionViewRow row;
    row.name = view.name;
    Divisions grid[kDivisionColumns];
    for (const ColumnMethod& c : kMethods) {
      DivisionOptions o;
      o.method = c.method;
      o.tolerance = tol;
      o.maxPerDirection = kUncapped;
      const Stopwatch stopwatch;
      grid[c.column] =
          patchDivisions(c.zeroWeight > 0 ? substituteZeroWeights(screen, c.zeroWeight) : screen, o);
      table.seconds[c.column] += stopwatch.elapsedSeconds();
      row.faces[c.column] = grid[c.column].divisionNumber();
    }
    // Measure the bounds' grids; search the true value below the smallest of them.
    const Divisions* known = &grid[kSplitColumn];
    for (DivisionColumn c : kBoundColumns) {
      row.deviation[c] = uniformGridDeviation(net, grid[c].nu, grid[c].nv);
      if (grid[c].divisionNumber() < known->divisionNumber()) known = &grid[c];
    }
    row.faces[kTruthColumn] =
        smallestUniformGrid(net, tol, known->nu, known->nv, {8, 64}).divisionNumber();
    table.views.push_back(row);
  }
  const double n = double(std::max<size_t>(1, table.views.size()));
  for (const DivisionViewRow& r : table.views) {
    for (int k = 0; k < kDivisionColumns; ++k) {
      table.average[k] += double(r.faces[k]) / n;
      table.worstRatio[k] =
          std::max(table.worstRatio[k], double(r.faces[k]) / double(r.faces[kTruthColumn]));
    }
    for (DivisionColumn c : kBoundColumns)
      table.worstDeviation = std::max(table.worstDeviation, r.deviation[c]);
  }
  return table;
}

std::string formatDivisionTable(const DivisionTable& table, bool perView) {
  std::string out;
  char line[512];
  std::snprintf(line, sizeof line,
                "Division numbers N_u*N_v at TOL %.3g px on a %dx%d viewport, averaged over %zu "
                "views with zero weights (paper 002, table 1)\n",
                table.tolerance, table.viewport, table.viewport, table.views.size());
  out += line;
  std::snprintf(line, sizeof line, "%-28s %18s %16s %16s %14s\n", "method", "division number",
                "over-division", "worst one view", "patches/s");
  out += line;
  const double views = double(table.views.size());
  for (int k = 0; k < kDivisionColumns; ++k) {
    const char* name = divisionColumnName(DivisionColumn(k));
    if (k == kTruthColumn) {
      std::snprintf(line, sizeof line, "%-28s %18.2f %16s\n", name, table.average[k], "-");
    } else {
      const double perSecond = table.seconds[k] > 0 ? views / table.seconds[k] : 0.0;
      std::snprintf(line, sizeof line, "%-28s %18.2f %16.3f %16.3f %14.1f\n", name,
                    table.average[k], table.ratio(DivisionColumn(k)), table.worstRatio[k],
                    perSecond);
    }
    out += line;
  }
  std::snprintf(line, sizeof line,
                "largest measured deviation of the bounds' grids (all but the substitutions): "
                "%.4f px (TOL %.3g); patches/s on one thread\n",
                table.worstDeviation, table.tolerance);
  out += line;
  if (perView) {
    std::snprintf(line, sizeof line, "\n%-64s %8s %14s %12s %8s %8s %8s %8s %8s\n", "view",
                  "split", "0->0.001", "0->0.01", "subdiv", "cellwise", "direct'l", "direct",
                  "true");
    out += line;
    for (const DivisionViewRow& r : table.views) {
      std::snprintf(line, sizeof line,
                    "%-64s %8lld %14lld %12lld %8lld %8lld %8lld %8lld %8lld\n", r.name.c_str(),
                    r.faces[kSplitColumn], r.faces[kWeight0001Column], r.faces[kWeight001Column],
                    r.faces[kSubdividedColumn], r.faces[kCellwiseColumn],
                    r.faces[kDirectionalColumn], r.faces[kDirectColumn], r.faces[kTruthColumn]);
      out += line;
    }
  }
  return out;
}

}  // namespace tessera
