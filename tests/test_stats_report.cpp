// The statistics report (host/io/stats_report.h, schema in docs/stats_schema.md): on the
// teapot, the report parses back, per-patch numbers add up to the totals, the leaves match the
// tree level by level, and the per-patch deviation agrees with one measurement of the whole mesh.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "mesh/deviation.h"
#include "io/bpt_reader.h"
#include "io/stats_report.h"
#include "mesh/tessellate.h"

using namespace tessera;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct TeapotRun {
  std::vector<BezierPatch> patches;
  Tessellation tessellation;
};

const TeapotRun& teapot() {
  static const TeapotRun run = [] {
    TeapotRun r;
    r.patches = readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt");
    Backend backend = makeMirrorBackend();
    QuadtreeOptions options;
    options.rule = SplitRule::SampledMax;
    r.tessellation = tessellate(r.patches, options, backend);
    return r;
  }();
  return run;
}

}  // namespace

TEST_CASE("stats: the teapot report adds up", "[stats]") {
  const TeapotRun& run = teapot();
  const Tessellation& t = run.tessellation;
  const PatchDeviation deviation = measureDeviationPerPatch(t, run.patches);
  // Through text and back, as a reader of the file sees it.
  const json report = json::parse(statsToJson(t, &deviation).dump(2));

  CHECK(report.at("schema") == "tessera-stats");
  CHECK(report.at("schemaVersion") == kStatsSchemaVersion);
  const json& totals = report.at("totals");
  CHECK(totals.at("patches") == run.patches.size());
  CHECK(totals.at("leaves") == t.tree.leaves.size());
  CHECK(totals.at("triangles") == t.mesh.triangleCount());
  CHECK(totals.at("vertices") == t.mesh.vertexCount());
  CHECK(totals.at("depth") == t.tree.depth);

  const json& patches = report.at("patches");
  REQUIRE(patches.size() == run.patches.size());
  size_t leaves = 0, triangles = 0, vertices = 0, samples = 0;
  uint32_t depth = 0;
  double maxDeviation = 0;
  std::vector<size_t> leavesByLevel;
  for (size_t p = 0; p < patches.size(); ++p) {
    const json& patch = patches[p];
    CHECK(patch.at("patch") == p);
    CHECK(patch.at("leaves").get<size_t>() > 0);
    leaves += patch.at("leaves").get<size_t>();
    triangles += patch.at("triangles").get<size_t>();
    vertices += patch.at("vertices").get<size_t>();
    depth = std::max(depth, patch.at("depth").get<uint32_t>());
    const auto byLevel = patch.at("leavesByLevel").get<std::vector<size_t>>();
    CHECK(byLevel.size() == patch.at("depth").get<size_t>() + 1);
    size_t patchLeaves = 0;
    for (size_t level = 0; level < byLevel.size(); ++level) {
      if (leavesByLevel.size() <= level) leavesByLevel.resize(level + 1, 0);
      leavesByLevel[level] += byLevel[level];
      patchLeaves += byLevel[level];
    }
    CHECK(patchLeaves == patch.at("leaves").get<size_t>());
    samples += patch.at("deviation").at("samples").get<size_t>();
    maxDeviation = std::max(maxDeviation, patch.at("deviation").at("max").get<double>());
  }
  CHECK(leaves == totals.at("leaves").get<size_t>());
  CHECK(triangles == totals.at("triangles").get<size_t>());
  CHECK(vertices == totals.at("vertices").get<size_t>());
  CHECK(depth == totals.at("depth").get<uint32_t>());

  // Levels: one entry per tree level, and the leaves the patches report per level are the
  // tree's own per-level leaf counts.
  const json& levels = report.at("levels");
  REQUIRE(levels.size() == t.stats.levels.size());
  size_t levelLeaves = 0;
  for (size_t level = 0; level < levels.size(); ++level) {
    const json& l = levels[level];
    CHECK(l.at("level") == t.stats.levels[level].level);
    CHECK(l.at("nodes") == t.stats.levels[level].nodes);
    CHECK(l.at("splits") == t.stats.levels[level].splits);
    CHECK(l.at("hostNodes") == t.stats.levels[level].hostNodes);
    for (const char* timing : {"classifyMs", "gpuMs", "frontierMs"})
      CHECK(l.at(timing).get<double>() >= 0);
    const size_t fromPatches =
        l.at("level").get<size_t>() < leavesByLevel.size() ? leavesByLevel[l.at("level")] : 0;
    CHECK(l.at("leaves") == fromPatches);
    levelLeaves += l.at("leaves").get<size_t>();
  }
  CHECK(levelLeaves == t.tree.leaves.size());

  // Deviation: the total is the largest per-patch value, and the same as one measurement of
  // the whole mesh (same samples; the mean only up to summation order).
  const DeviationReport whole = measureDeviation(t, run.patches);
  const json& d = totals.at("deviation");
  CHECK(d.at("max").get<double>() == maxDeviation);
  CHECK(d.at("max").get<double>() == whole.maxDeviation);
  CHECK(d.at("samples") == samples);
  CHECK(d.at("samples") == whole.samples);
  CHECK(d.at("mean").get<double>() == Approx(whole.meanDeviation).epsilon(1e-9));
  CHECK(d.at("subdivisions") == 4);
  CHECK(d.at("max").get<double>() > 0);
  const size_t worst = d.at("worstTriangle");
  CHECK(worst < t.mesh.triangleCount());

  const json& timings = report.at("timings");
  for (const char* timing : {"treeMs", "triangulateMs", "evaluateMs", "totalMs", "deviationMs"})
    CHECK(timings.at(timing).get<double>() >= 0);
}

TEST_CASE("stats: without deviation or a tessellation the sections are null or absent", "[stats]") {
  const Tessellation& t = teapot().tessellation;
  const json full = statsToJson(t);
  CHECK(full.at("totals").at("deviation").is_null());
  CHECK(full.at("timings").at("deviationMs").is_null());
  CHECK(full.at("patches").at(0).at("deviation").is_null());

  const json summary = statsToJson(t.stats);
  CHECK_FALSE(summary.contains("patches"));
  CHECK(summary.at("totals").at("leaves") == t.stats.leaves);
  CHECK(summary.at("levels").size() == t.stats.levels.size());
}

TEST_CASE("stats: options are written as given", "[stats]") {
  QuadtreeOptions options;
  options.rule = SplitRule::TrueMax;
  options.linearity = 0.1f;
  options.flatness = 0.3f;
  const json o = optionsToJson(options);
  CHECK(o.at("method") == "D");
  CHECK(o.at("linearity").get<double>() == 0.1);  // the shortest decimal, not 0.100000001…
  CHECK(o.at("flatness").get<double>() == 0.3);
  CHECK(o.at("maxDepth") == options.maxDepth);
}

TEST_CASE("stats: writeStatsFile writes the report as JSON text", "[stats]") {
  const fs::path dir = fs::temp_directory_path() /
                       ("tessera_test_stats_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path path = dir / "stats.json";
  json report = statsToJson(teapot().tessellation.stats);
  report["run"] = {{"input", "caf\xC3\xA9.bpt"}, {"badly encoded", "\xFF"}};
  writeStatsFile(path.string(), report);
  std::ifstream in(path);
  const json back = json::parse(in);
  CHECK(back.at("totals") == report.at("totals"));
  CHECK(back.at("run").at("input") == "caf\xC3\xA9.bpt");
  CHECK(back.at("run").at("badly encoded") == "\xEF\xBF\xBD");  // U+FFFD, not an exception
  std::error_code ec;
  fs::remove_all(dir, ec);
}

TEST_CASE("stats: the lower bound and the ratio", "[stats][lower_bound]") {
  const TeapotRun& run = teapot();
  json report = statsToJson(run.tessellation);
  addUncomputedLowerBound(report);
  for (const char* key : {"lowerBoundTriangles", "lowerBoundTolerance", "lowerBoundRatio"})
    CHECK(report.at("totals").at(key).is_null());
  CHECK(report.at("timings").at("lowerBoundMs").is_null());

  const TriangleLowerBound bound = asymptoticTriangleLowerBound(run.patches, 0.01);
  addLowerBound(report, bound);
  report = json::parse(report.dump());
  const json& totals = report.at("totals");
  const double ratio = totals.at("lowerBoundRatio").get<double>();
  std::printf("teapot rule C: %zu triangles, N_min(0.01) %.1f, ratio %.3f\n",
              run.tessellation.mesh.triangleCount(), bound.triangles, ratio);
  CHECK(totals.at("lowerBoundTriangles").get<double>() == bound.triangles);
  CHECK(totals.at("lowerBoundTolerance").get<double>() == 0.01);
  CHECK(ratio == Approx(double(run.tessellation.mesh.triangleCount()) / bound.triangles));
  CHECK(report.at("timings").at("lowerBoundMs").get<double>() >= 0.0);

  // A flat surface has N_min = 0: the ratio is null, not infinite.
  TriangleLowerBound flat;
  flat.tolerance = 0.01;
  addLowerBound(report, flat);
  CHECK(report.at("totals").at("lowerBoundRatio").is_null());
}
