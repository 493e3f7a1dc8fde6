#include "io/stats_report.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <stdexcept>

#include "common/stopwatch.h"
#include "io/atomic_file.h"
#include "mesh/screen_tolerance.h"

namespace tessera {
namespace {

struct PatchCounts {
  uint32_t depth = 0;
  size_t leaves = 0, triangles = 0, vertices = 0;
  std::vector<size_t> leavesByLevel;
};

// Leaves come from the tree, triangles from the tessellation's per-triangle patch. Vertices
// are welded where patches meet, so a patch's "vertices" are those evaluated on it (mesh
// patchIds): each vertex counts once, for one of the patches that share it.
std::vector<PatchCounts> countPerPatch(const Tessellation& t) {
  std::vector<PatchCounts> counts(t.stats.patches);
  auto patch = [&](uint32_t index) -> PatchCounts& {
    if (index >= counts.size())
      throw std::invalid_argument("statsToJson: patch index " + std::to_string(index) +
                                  " for " + std::to_string(counts.size()) + " patches");
    return counts[index];
  };
  for (const QuadLeaf& leaf : t.tree.leaves) {
    PatchCounts& c = patch(leaf.patchIndex);
    ++c.leaves;
    c.depth = std::max(c.depth, leaf.level);
    if (c.leavesByLevel.size() <= leaf.level) c.leavesByLevel.resize(leaf.level + 1, 0);
    ++c.leavesByLevel[leaf.level];
  }
  const TriangleMesh& mesh = t.mesh;
  if (mesh.patchIds.size() != mesh.positions.size() ||
      t.trianglePatch.size() != mesh.triangleCount())
    throw std::invalid_argument("statsToJson: vertex or triangle patch ids missing");
  for (uint32_t id : mesh.patchIds) ++patch(id).vertices;
  for (uint32_t id : t.trianglePatch) ++patch(id).triangles;
  return counts;
}

nlohmann::json deviationToJson(const DeviationReport& d) {
  return {{"max", d.maxDeviation},
          {"mean", d.meanDeviation},
          {"samples", d.samples},
          {"worstTriangle", d.samples ? nlohmann::json(d.worstTriangle) : nlohmann::json()}};
}

// The double nearest to the shortest decimal that reads back as `value`: the option given as
// 0.1 shows as 0.1 in the report, not as the float's exact 0.10000000149011612.
double shortestDecimal(float value) {
  char digits[32];
  const auto end = std::to_chars(digits, digits + sizeof digits, value).ptr;
  double result = value;
  std::from_chars(digits, end, result);
  return result;
}

}  // namespace

PatchDeviation measureDeviationPerPatch(const Tessellation& t,
                                        const std::vector<BezierPatch>& patches,
                                        int subdivisions, DeviationMetric metric) {
  const Stopwatch stopwatch;
  // One pass over the whole mesh (on all cores) already gathers every patch's numbers.
  const DeviationReport whole = measureDeviation(t, patches, subdivisions, metric);
  PatchDeviation result;
  result.subdivisions = subdivisions;
  result.perPatch.resize(patches.size());
  for (size_t p = 0; p < patches.size(); ++p) {
    DeviationReport& d = result.perPatch[p];
    d.samples = whole.perPatchSamples[p];
    if (d.samples == 0) continue;
    d.maxDeviation = whole.perPatchMax[p];
    d.meanDeviation = whole.perPatchMean[p];
    d.worstTriangle = whole.perPatchWorstTriangle[p];
  }
  result.total = whole;
  result.ms = stopwatch.elapsedMs();
  return result;
}

void addGeometricDeviation(nlohmann::json& report, const PatchDeviation& geometric) {
  report["totals"]["geometricDeviation"] = deviationToJson(geometric.total);
  nlohmann::json& patches = report["patches"];
  if (patches.size() != geometric.perPatch.size())
    throw std::invalid_argument("addGeometricDeviation: " + std::to_string(geometric.perPatch.size()) +
                                " patches measured, " + std::to_string(patches.size()) + " in the report");
  for (size_t p = 0; p < patches.size(); ++p)
    patches[p]["geometricDeviation"] = deviationToJson(geometric.perPatch[p]);
  report["timings"]["geometricDeviationMs"] = geometric.ms;
}

void addUnmeasuredGeometricDeviation(nlohmann::json& report) {
  report["totals"]["geometricDeviation"] = nullptr;
  for (nlohmann::json& patch : report["patches"]) patch["geometricDeviation"] = nullptr;
  report["timings"]["geometricDeviationMs"] = nullptr;
}

void addLowerBound(nlohmann::json& report, const TriangleLowerBound& bound) {
  nlohmann::json& totals = report["totals"];
  const double triangles = totals.at("triangles").get<double>();
  totals["lowerBoundTriangles"] = bound.triangles;
  totals["lowerBoundTolerance"] = bound.tolerance;
  totals["lowerBoundRatio"] =
      bound.triangles > 0.0 ? nlohmann::json(triangles / bound.triangles) : nlohmann::json();
  report["timings"]["lowerBoundMs"] = bound.ms;
}

void addUncomputedLowerBound(nlohmann::json& report) {
  for (const char* key : {"lowerBoundTriangles", "lowerBoundTolerance", "lowerBoundRatio"})
    report["totals"][key] = nullptr;
  report["timings"]["lowerBoundMs"] = nullptr;
}

nlohmann::json statsToJson(const TessellationStats& s) {
  nlohmann::json levels = nlohmann::json::array();
  for (const LevelStats& l : s.levels)
    levels.push_back({{"level", l.level},
                      {"nodes", l.nodes},
                      {"splits", l.splits},
                      {"leaves", l.leaves},
                      {"classifyMs", l.classifyMs},
                      {"gpuMs", l.gpuMs},
                      {"frontierMs", l.frontierMs},
                      {"hostNodes", l.hostNodes}});
  return {{"schema", "tessera-stats"},
          {"schemaVersion", kStatsSchemaVersion},
          {"totals",
           {{"patches", s.patches},
            {"depth", s.depth},
            {"leaves", s.leaves},
            {"triangles", s.triangles},
            {"vertices", s.vertices},
            {"degenerateTrianglesDropped", s.degenerateTrianglesDropped},
            {"deviation", nullptr}}},
          {"timings",
           {{"treeMs", s.treeMs},
            {"triangulateMs", s.triangulateMs},
            {"evaluateMs", s.evaluateMs},
            {"totalMs", s.totalMs},
            {"deviationMs", nullptr}}},
          {"levels", std::move(levels)}};
}

nlohmann::json statsToJson(const Tessellation& t, const PatchDeviation* deviation) {
  nlohmann::json report = statsToJson(t.stats);
  if (deviation && deviation->perPatch.size() != t.stats.patches)
    throw std::invalid_argument("statsToJson: deviation for " +
                                std::to_string(deviation->perPatch.size()) + " patches, " +
                                std::to_string(t.stats.patches) + " tessellated");
  if (deviation) {
    report["totals"]["deviation"] = deviationToJson(deviation->total);
    report["totals"]["deviation"]["subdivisions"] = deviation->subdivisions;
    report["timings"]["deviationMs"] = deviation->ms;
  }
  const std::vector<PatchCounts> counts = countPerPatch(t);
  nlohmann::json patches = nlohmann::json::array();
  for (size_t p = 0; p < counts.size(); ++p) {
    const PatchCounts& c = counts[p];
    patches.push_back({{"patch", p},
                       {"depth", c.depth},
                       {"leaves", c.leaves},
                       {"leavesByLevel", c.leavesByLevel},
                       {"triangles", c.triangles},
                       {"vertices", c.vertices},
                       {"deviation", deviation ? deviationToJson(deviation->perPatch[p])
                                               : nlohmann::json()}});
  }
  report["patches"] = std::move(patches);
  report["tolerance"] = nullptr;
  return report;
}

void addToleranceReport(nlohmann::json& report, const Tessellation& t, const ToleranceSpec& spec,
                        double resolved) {
  nlohmann::json& patches = report["patches"];
  if (patches.size() != t.stats.patches)
    throw std::invalid_argument("addToleranceReport: " + std::to_string(patches.size()) +
                                " patches in the report, " + std::to_string(t.stats.patches) +
                                " tessellated");
  std::vector<double> perPatch(patches.size(), 0.0);
  for (const QuadLeaf& leaf : t.tree.leaves)
    perPatch.at(leaf.patchIndex) =
        std::max(perPatch.at(leaf.patchIndex), double(leaf.flatness) * t.tree.boundScale);
  for (size_t p = 0; p < patches.size(); ++p) patches[p]["largestLeafBound"] = perPatch[p];
  // In pixels (screen space) the bound is over the leaves in view: culled ones are unseen,
  // eye-plane ones unproven (mesh/screen_tolerance.h); they are counted instead.
  const ScreenLeafCounts screen = screenLeafCounts(t.tree);
  const double bound = spec.pixels ? screen.largestBound : largestLeafBound(t.tree);
  addToleranceBound(report, spec, resolved, bound, t.stats.diagonalFans,
                    spec.pixels ? &screen : nullptr);
}

void addToleranceBound(nlohmann::json& report, const ToleranceSpec& spec, double resolved,
                       double bound, size_t diagonalFans, const ScreenLeafCounts* screen) {
  report["tolerance"] = {
      {"requested", resolved},
      {"given", spec.text},
      {"relative", spec.relative},
      {"pixels", spec.pixels},
      {"diagonal", spec.relative ? nlohmann::json(resolved / spec.value) : nlohmann::json()},
      {"largestLeafBound", bound},
      {"diagonalFans", diagonalFans},
      {"provenWithin", bound <= resolved && diagonalFans == 0},
      {"culledLeaves", screen ? nlohmann::json(screen->culled) : nlohmann::json()},
      {"eyePlaneLeaves", screen ? nlohmann::json(screen->eyePlane) : nlohmann::json()}};
}

nlohmann::json optionsToJson(const QuadtreeOptions& o) {
  return {{"method", std::string(1, splitRuleLetter(o.rule))},
          {"linearity", shortestDecimal(o.linearity)},
          {"flatness", shortestDecimal(o.flatness)},
          {"maxDepth", o.maxDepth},
          {"minSize", shortestDecimal(o.minSize)},
          {"samples", o.samples},
          {"gridU", o.gridU},
          {"gridV", o.gridV},
          {"tolerance", o.rule == SplitRule::Tolerance ? nlohmann::json(o.tolerance)
                                                       : nlohmann::json()},
          {"nodeBudget", o.nodeBudget}};
}

void writeStats(std::ostream& out, const nlohmann::json& report) {
  // Invalid UTF-8 (a file name from a non-UTF-8 locale) becomes U+FFFD instead of throwing.
  const std::string text =
      report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  out.write(text.data(), std::streamsize(text.size()));
}

void writeStatsFile(const std::string& path, const nlohmann::json& report) {
  writeFileAtomically(path, [&](std::ostream& out) { writeStats(out, report); });
}

void addWarnings(nlohmann::json& report, const std::vector<ResultWarning>& warnings) {
  nlohmann::json list = nlohmann::json::array();
  for (const ResultWarning& w : warnings) list.push_back({{"code", w.code}, {"message", w.message}});
  report["warnings"] = list;
}

}  // namespace tessera
