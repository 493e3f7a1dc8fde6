#include "io/stats_report.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <limits>
#include <stdexcept>

#include "io/atomic_file.h"

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
  const auto start = std::chrono::steady_clock::now();
  const TriangleMesh& mesh = t.mesh;
  if (t.trianglePatch.size() != mesh.triangleCount() || t.cornerUv.size() != mesh.indices.size())
    throw std::invalid_argument(
        "measureDeviationPerPatch: per-triangle patches and corner uvs missing");
  // The triangles of each patch, by index into the whole mesh.
  std::vector<std::vector<size_t>> trianglesOf(patches.size());
  for (size_t tri = 0; tri < mesh.triangleCount(); ++tri) {
    const uint32_t id = t.trianglePatch[tri];
    if (id >= patches.size())
      throw std::invalid_argument("measureDeviationPerPatch: patch " + std::to_string(id) +
                                  " for " + std::to_string(patches.size()) + " patches");
    trianglesOf[id].push_back(tri);
  }

  PatchDeviation result;
  result.subdivisions = subdivisions;
  result.perPatch.resize(patches.size());
  constexpr uint32_t kUnmapped = std::numeric_limits<uint32_t>::max();
  std::vector<uint32_t> remap(mesh.vertexCount(), kUnmapped);
  double sampleSum = 0;
  for (size_t p = 0; p < patches.size(); ++p) {
    if (trianglesOf[p].empty()) continue;
    // A compact copy of this patch's triangles with what measureDeviation reads: positions,
    // indices, and per triangle its patch and corner uvs.
    Tessellation sub;
    std::vector<uint32_t> used;
    for (size_t tri : trianglesOf[p]) {
      for (int corner = 0; corner < 3; ++corner) {
        const uint32_t v = mesh.indices[3 * tri + corner];
        if (remap[v] == kUnmapped) {
          remap[v] = uint32_t(sub.mesh.positions.size());
          used.push_back(v);
          sub.mesh.positions.push_back(mesh.positions[v]);
        }
        sub.mesh.indices.push_back(remap[v]);
        sub.cornerUv.push_back(t.cornerUv[3 * tri + corner]);
      }
      sub.trianglePatch.push_back(uint32_t(p));
    }
    for (uint32_t v : used) remap[v] = kUnmapped;

    DeviationReport d = measureDeviation(sub, patches, subdivisions, metric);
    d.worstTriangle = trianglesOf[p][d.worstTriangle];
    result.perPatch[p] = d;
    sampleSum += d.meanDeviation * double(d.samples);
    result.total.samples += d.samples;
    if (d.maxDeviation > result.total.maxDeviation) {
      result.total.maxDeviation = d.maxDeviation;
      result.total.worstTriangle = d.worstTriangle;
    }
  }
  result.total.meanDeviation = result.total.samples ? sampleSum / double(result.total.samples) : 0;
  result.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                  .count();
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

nlohmann::json statsToJson(const TessellationStats& s) {
  nlohmann::json levels = nlohmann::json::array();
  for (const LevelStats& l : s.levels)
    levels.push_back({{"level", l.level},
                      {"nodes", l.nodes},
                      {"splits", l.splits},
                      {"leaves", l.leaves},
                      {"classifyMs", l.classifyMs},
                      {"gpuMs", l.gpuMs},
                      {"frontierMs", l.frontierMs}});
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
  return report;
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
          {"nodeBudget", o.nodeBudget}};
}

void writeStatsFile(const std::string& path, const nlohmann::json& report) {
  // Invalid UTF-8 (a file name from a non-UTF-8 locale) becomes U+FFFD instead of throwing.
  const std::string text =
      report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  writeFileAtomically(path, [&](std::ostream& out) {
    out.write(text.data(), std::streamsize(text.size()));
  });
}

}  // namespace tessera
