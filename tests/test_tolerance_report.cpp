// Rule T's part of the statistics report (addToleranceReport, docs/stats_schema.md): null for
// the other rules; once filled, the requested δ as given, the largest leaf bound over all leaves
// and per patch (the bound rule T keeps in QuadLeaf::flatness), and whether it is proven within.
// The plumbing is checked on a tree whose leaves carry known values, so it holds whatever the
// classifier computes.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>

#include "io/bpt_reader.h"
#include "io/stats_report.h"
#include "mesh/tessellate.h"

using namespace tessera;

TEST_CASE("stats: the tolerance member is null for rules A-D and filled for rule T",
          "[stats][tolerance]") {
  const std::vector<BezierPatch> patches = readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt");
  Backend backend = makeMirrorBackend();
  QuadtreeOptions options;
  options.rule = SplitRule::Midpoint;
  Tessellation t = tessellate(patches, options, backend);
  nlohmann::json report = statsToJson(t);
  REQUIRE(report.contains("tolerance"));
  REQUIRE(report["tolerance"].is_null());
  REQUIRE(optionsToJson(options)["tolerance"].is_null());

  // Give each leaf a distinct "bound" so the per-patch and total maxima are known. Bounds are
  // in the units of the tree's local frame: × boundScale (the frame's scale) in model units.
  REQUIRE(t.tree.boundScale == t.frame.scale);
  std::vector<double> expected(patches.size(), 0.0);
  for (size_t k = 0; k < t.tree.leaves.size(); ++k) {
    QuadLeaf& leaf = t.tree.leaves[k];
    leaf.flatness = 1e-4f * float((k * 7919) % 1000 + 1);
    expected[leaf.patchIndex] =
        std::max(expected[leaf.patchIndex], double(leaf.flatness) * t.tree.boundScale);
  }
  const double largest = *std::max_element(expected.begin(), expected.end());
  REQUIRE(largestLeafBound(t.tree) == largest);

  const std::vector<BezierPatch>& model = patches;
  const ToleranceSpec spec = parseTolerance("1%");
  const double resolved = resolveTolerance(spec, model);
  addToleranceReport(report, t, spec, resolved);
  const nlohmann::json& tol = report["tolerance"];
  INFO(tol.dump());
  REQUIRE(tol["requested"] == resolved);
  REQUIRE(tol["given"] == "1%");
  REQUIRE(tol["relative"] == true);
  REQUIRE(tol["diagonal"].get<double>() == Approx(controlPointDiagonal(model)).epsilon(1e-12));
  REQUIRE(tol["largestLeafBound"] == largest);
  REQUIRE(tol["diagonalFans"] == 0);
  REQUIRE(tol["provenWithin"] == (largest <= resolved));
  for (size_t p = 0; p < patches.size(); ++p)
    REQUIRE(report["patches"][p]["largestLeafBound"] == expected[p]);

  // Model units: no diagonal; a δ above every bound is proven, one below it is not.
  addToleranceReport(report, t, parseTolerance("0.5"), 0.5);
  REQUIRE(report["tolerance"]["diagonal"].is_null());
  REQUIRE(report["tolerance"]["relative"] == false);
  REQUIRE(report["tolerance"]["provenWithin"] == (largest <= 0.5));
  addToleranceReport(report, t, parseTolerance("1e-9"), 1e-9);
  REQUIRE(report["tolerance"]["provenWithin"] == false);

  // A leaf proven for one diagonal but fanned holds only its any-triangle bound, which may pass
  // δ: the report counts such leaves and then proves nothing, whatever the largest leaf bound.
  REQUIRE(largest <= 0.5);
  t.stats.diagonalFans = 3;
  addToleranceReport(report, t, parseTolerance("0.5"), 0.5);
  REQUIRE(report["tolerance"]["diagonalFans"] == 3);
  REQUIRE(report["tolerance"]["provenWithin"] == false);
  addToleranceBound(report, parseTolerance("0.5"), 0.5, largest, 0);
  REQUIRE(report["tolerance"]["provenWithin"] == true);
  addToleranceBound(report, parseTolerance("0.5"), 0.5, largest, 1);
  REQUIRE(report["tolerance"]["provenWithin"] == false);

  options.rule = SplitRule::Tolerance;
  options.tolerance = 0.25;
  REQUIRE(optionsToJson(options)["tolerance"] == 0.25);
}
