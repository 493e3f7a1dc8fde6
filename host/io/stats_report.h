// The tessellation statistics as a JSON report (schema: docs/stats_schema.md): totals, the
// per-level classification and timings, and per-patch depth, leaves, triangles, vertices and
// deviation from the surface. For scripts, dashboards and regression tracking; the CLI's
// `--stats FILE` and `--json` write it.
#pragma once
#include <nlohmann/json_fwd.hpp>

#include <ostream>
#include <string>
#include <vector>

#include "mesh/deviation.h"
#include "mesh/lower_bound.h"
#include "mesh/result_warnings.h"
#include "geometry/patch.h"
#include "quadtree/quadtree.h"
#include "quadtree/tolerance.h"
#include "mesh/tessellate.h"

namespace tessera {

struct ScreenLeafCounts;  // mesh/screen_tolerance.h

// Every report has "schema": "tessera-stats" and "schemaVersion": this; it is bumped when a
// member changes meaning or goes away (adding members does not bump it).
constexpr int kStatsSchemaVersion = 1;

// measureDeviation (host/mesh/deviation.h) over the whole mesh, once, split by patch: the total is
// that measurement, each patch's entry its samples, max, mean and worst triangle (an index
// into the whole mesh's triangles).
struct PatchDeviation {
  std::vector<DeviationReport> perPatch;  // one per patch, samples == 0 for a patch without triangles
  DeviationReport total;
  int subdivisions = 0;
  double ms = 0;  // time the measurement took
};

// `patches` are the ones tessellated into `tessellation`.
PatchDeviation measureDeviationPerPatch(const Tessellation& tessellation,
                                        const std::vector<BezierPatch>& patches,
                                        int subdivisions = 4,
                                        DeviationMetric metric = DeviationMetric::Parametric);

// Adds the geometric metric's numbers beside the parametric ones of a full report:
// totals.geometricDeviation and patches[].geometricDeviation ({max, mean, samples,
// worstTriangle}), and timings.geometricDeviationMs.
void addGeometricDeviation(nlohmann::json& report, const PatchDeviation& geometric);
// The same keys as null, for a report whose deviation was not measured (the CLI without
// --deviation), so a reader finds every key whether or not it was measured.
void addUnmeasuredGeometricDeviation(nlohmann::json& report);

// The asymptotic lower bound (host/mesh/lower_bound.h) beside a full report:
// totals.lowerBoundTriangles (N_min at bound.tolerance), totals.lowerBoundTolerance (that δ),
// totals.lowerBoundRatio (totals.triangles / N_min; null where N_min is 0, a flat surface) and
// timings.lowerBoundMs.
void addLowerBound(nlohmann::json& report, const TriangleLowerBound& bound);
// The same keys as null, for a report without the bound.
void addUncomputedLowerBound(nlohmann::json& report);

// The report's "warnings": one {"code", "message"} object per condition of
// findResultWarnings (host/mesh/result_warnings.h); an empty array when there is none.
void addWarnings(nlohmann::json& report, const std::vector<ResultWarning>& warnings);

// Totals, timings and per-level numbers only (no per-patch section).
nlohmann::json statsToJson(const TessellationStats& stats);

// The full report: the above plus "patches" (leaves from the tree, triangles from
// trianglePatch, vertices from the mesh's patchIds: welded vertices count for the patch they
// were evaluated on, so the per-patch numbers add up to the totals) and, when `deviation` is given, deviation totals and per patch (null otherwise).
nlohmann::json statsToJson(const Tessellation& tessellation,
                           const PatchDeviation* deviation = nullptr);

// Fills the report's "tolerance" member (null in every report until then, i.e. for rules A–D)
// for a rule-T run at δ = `resolved` model units given as `spec`: requested, given, relative,
// diagonal, largestLeafBound, diagonalFans, provenWithin (largestLeafBound ≤ requested and no
// diagonal fan); and patches[].largestLeafBound. docs/stats_schema.md.
void addToleranceReport(nlohmann::json& report, const Tessellation& tessellation,
                        const ToleranceSpec& spec, double resolved);
// The "tolerance" member alone, from the largest leaf bound `bound` (model units, or pixels
// with `screen`'s counts) and the count of leaves proven for one diagonal that the triangulator
// fanned (TessellationStats::diagonalFans: they hold only their any-triangle bound, so the run
// is not proven within δ): for a streamed run, which holds no tree.
void addToleranceBound(nlohmann::json& report, const ToleranceSpec& spec, double resolved,
                       double bound, size_t diagonalFans,
                       const ScreenLeafCounts* screen = nullptr);

// The quad-tree options as a JSON object, for the report's optional "run" section.
nlohmann::json optionsToJson(const QuadtreeOptions& options);

// Writes report.dump(2) and a newline via writeFileAtomically (InputError of kind Io on
// failure; the file is whole or untouched).
void writeStatsFile(const std::string& path, const nlohmann::json& report);
// The same text into `out` (for AtomicFileGroup::stage).
void writeStats(std::ostream& out, const nlohmann::json& report);

}  // namespace tessera
