// The comparison of paper 002 (host/experiments/division_table.h) at its default settings, as
// `tessera divisions` prints it: the beyond-the-paper goal of issue #5 (over-division ≤ 2 on
// average, measured deviation ≤ TOL on every surface and viewpoint), the order of the methods,
// and the true value below every bound. The numbers are in docs/rational_division.md.
#include <catch2/catch.hpp>

#include "experiments/division_table.h"

using namespace tessera;

TEST_CASE("Division table: direct and directional bounds over-divide at most 2x, grids within TOL",
          "[division]") {
  const DivisionTableOptions options;
  const DivisionTable table = divisionComparison(options);
  REQUIRE(table.views.size() >= 20);
  WARN(formatDivisionTable(table, false));
  CHECK(table.ratio(kDirectColumn) <= 1.2);  // the goal is ≤ 2; direct reaches ~1.04
  CHECK(table.worstRatio[kDirectColumn] <= 1.5);
  CHECK(table.ratio(kDirectionalColumn) <= 2.0);
  CHECK(table.ratio(kDirectColumn) < table.ratio(kDirectionalColumn));
  CHECK(table.ratio(kDirectionalColumn) < table.ratio(kCellwiseColumn));
  CHECK(table.ratio(kCellwiseColumn) < table.ratio(kSubdividedColumn));
  CHECK(table.ratio(kSubdividedColumn) < table.ratio(kSplitColumn));
  CHECK(table.ratio(kWeight001Column) > 100.0 * table.ratio(kSplitColumn));
  CHECK(table.ratio(kWeight0001Column) > table.ratio(kWeight001Column));
  CHECK(table.worstDeviation <= options.tolerance);
  for (const DivisionViewRow& row : table.views) {
    INFO(row.name);
    CHECK(row.faces[kTruthColumn] >= 1);
    for (DivisionColumn c : kBoundColumns) {
      INFO(divisionColumnName(c));
      CHECK(row.deviation[c] <= options.tolerance);
      // The true value is searched below every bound's grid.
      CHECK(row.faces[kTruthColumn] <= row.faces[c]);
    }
    // Each beyond-the-paper method searches below the subdivided grid.
    CHECK(row.faces[kCellwiseColumn] <= row.faces[kSubdividedColumn]);
    CHECK(row.faces[kDirectionalColumn] <= row.faces[kSubdividedColumn]);
    CHECK(row.faces[kDirectColumn] <= row.faces[kSubdividedColumn]);
  }
}
