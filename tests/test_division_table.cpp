// The comparison of paper 002 (host/division_table.h) at its default settings, as
// `tessera divisions` prints it: the beyond-the-paper goal of issue #5 (over-division ≤ 2 on
// average, measured deviation ≤ TOL on every surface and viewpoint) and the order of the
// methods. The table's own numbers are in docs/rational_division.md.
#include <catch2/catch.hpp>

#include "division_table.h"

using namespace tessera;

TEST_CASE("Division table: the directional bound over-divides at most 2x, every grid within TOL",
          "[division]") {
  const DivisionTableOptions options;
  const DivisionTable table = divisionComparison(options);
  REQUIRE(table.views.size() >= 20);
  const double truth = table.average[6];
  const double ratio[6] = {table.average[0] / truth, table.average[1] / truth,
                           table.average[2] / truth, table.average[3] / truth,
                           table.average[4] / truth, table.average[5] / truth};
  WARN(formatDivisionTable(table, false));
  CHECK(ratio[5] <= 2.0);                       // directional: the goal
  CHECK(ratio[5] < ratio[4]);                   // directional < cellwise
  CHECK(ratio[4] < ratio[3]);                   // cellwise < subdivided
  CHECK(ratio[3] < ratio[0]);                   // subdivided < split
  CHECK(ratio[2] > 100.0 * ratio[0]);           // substitution over-divides by orders
  CHECK(ratio[1] > ratio[2]);                   // the smaller substitute, the worse
  CHECK(table.worstDeviation <= options.tolerance);
  for (const DivisionViewRow& row : table.views) {
    INFO(row.name);
    CHECK(row.directionalDeviation <= options.tolerance);
    CHECK(row.cellwiseDeviation <= options.tolerance);
    CHECK(row.truth >= 1);
    // Every method's grid passes, and the true value is the smallest passing grid searched.
    CHECK(row.truth <= row.directional);
    CHECK(row.directional <= row.subdivided);
    CHECK(row.cellwise <= row.subdivided);
  }
}
