// The warnings of host/mesh/result_warnings.h, on both sides of each condition: the bump of
// data/scene_example.json flattened to 2 triangles by rules B and D is caught, the tea set's
// default runs (rule T, and rules A–D at the paper's thresholds) warn about nothing, an empty
// mesh, zero normals and a measured deviation are each named.
#include <catch2/catch.hpp>

#include <string>

#include "io/bpt_reader.h"
#include "io/surface_reader.h"
#include "mesh/result_warnings.h"
#include "mesh/tessellate.h"
#include "quadtree/tolerance.h"

using namespace tessera;

namespace {

std::string codes(const std::vector<ResultWarning>& warnings) {
  std::string text;
  for (const ResultWarning& w : warnings) text += w.code + " ";
  return text;
}

QuadtreeOptions ruleOptions(SplitRule rule, const std::vector<BezierPatch>& patches) {
  QuadtreeOptions o;
  o.rule = rule;
  if (rule == SplitRule::Tolerance) {
    o.tolerance = resolveTolerance(parseTolerance("0.1%"), patches);
    o.maxDepth = kToleranceMaxDepth;
  }
  return o;
}

}  // namespace

TEST_CASE("warnings: the scene example's bump flattened by rules B and D", "[warnings]") {
  const std::vector<BezierPatch> patches =
      readSurfaceFile(TESSERA_SOURCE_DIR "/data/scene_example.json");
  Backend cpu = makeMirrorBackend();
  const double bump = cornerPlaneDistanceRatio(patches[0]);
  WARN("the bump lies up to " << bump << " × its size off its corners' plane");
  for (SplitRule rule : {SplitRule::Midpoint, SplitRule::TrueMax}) {
    const Tessellation t = tessellate(patches, ruleOptions(rule, patches), cpu);
    const std::vector<ResultWarning> w = findResultWarnings(t, patches);
    INFO("rule " << splitRuleLetter(rule) << ": " << codes(w));
    REQUIRE(w.size() == 1);
    CHECK(w[0].code == "flattened-patch");
    CHECK(w[0].message.find("patch 0 got at most 2 triangles") == 0);
  }
  // Rule T splits the bump and so does not warn.
  const Tessellation t = tessellate(patches, ruleOptions(SplitRule::Tolerance, patches), cpu);
  CHECK(codes(findResultWarnings(t, patches)).empty());
}

TEST_CASE("warnings: none for the tea set's default runs", "[warnings]") {
  Backend cpu = makeMirrorBackend();
  double worstSmallPatch = 0;  // the largest corner-plane ratio of a patch of ≤ 2 triangles
  for (const char* model : {"teapot", "teacup", "teaspoon"}) {
    const std::vector<BezierPatch> patches =
        readBpt(std::string(TESSERA_SOURCE_DIR "/data/") + model + ".bpt");
    for (SplitRule rule : {SplitRule::Tolerance, SplitRule::UniformGrid, SplitRule::Midpoint,
                           SplitRule::SampledMax, SplitRule::TrueMax}) {
      const Tessellation t = tessellate(patches, ruleOptions(rule, patches), cpu);
      const std::vector<ResultWarning> w = findResultWarnings(t, patches);
      INFO(model << " rule " << splitRuleLetter(rule) << ": " << codes(w)
                 << (w.empty() ? "" : w[0].message));
      CHECK(w.empty());
      std::vector<size_t> triangles(patches.size(), 0);
      for (uint32_t p : t.trianglePatch) ++triangles[p];
      for (size_t p = 0; p < patches.size(); ++p)
        if (triangles[p] <= 2)
          worstSmallPatch = std::max(worstSmallPatch, cornerPlaneDistanceRatio(patches[p]));
    }
  }
  WARN("tea set: largest corner-plane ratio of a patch left with <= 2 triangles "
       << worstSmallPatch << " (flagged above " << kFlattenedFraction << ")");
  CHECK(worstSmallPatch <= kFlattenedFraction);
}

TEST_CASE("warnings: no triangles, zero normals, a large measured deviation", "[warnings]") {
  // A patch collapsed to one point gives no triangle at all.
  BezierPatch point;
  point.cp.assign(16, glm::dvec3(1, 2, 3));
  Backend cpu = makeMirrorBackend();
  const Tessellation empty = tessellate({point}, QuadtreeOptions{}, cpu);
  REQUIRE(empty.mesh.triangleCount() == 0);
  const std::vector<ResultWarning> none = findResultWarnings(empty, {point});
  REQUIRE(none.size() == 1);
  CHECK(none[0].code == "no-triangles");

  // A flat square whose one vertex has lost its normal.
  BezierPatch square;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) square.cp.push_back({i, j, 0});
  QuadtreeOptions grid;
  grid.rule = SplitRule::UniformGrid;
  grid.gridU = grid.gridV = 2;
  Tessellation t = tessellate({square}, grid, cpu);
  CHECK(findResultWarnings(t, {square}).empty());
  t.mesh.normals[t.mesh.indices[4]] = glm::vec3(0.0f);
  std::vector<ResultWarning> w = findResultWarnings(t, {square});
  REQUIRE(w.size() == 1);
  CHECK(w[0].code == "zero-normals");
  CHECK(w[0].message.find("1 vertex has no normal") == 0);

  // A measured deviation of 1 on a patch of size sqrt(18) ≈ 4.24 is 24% of it.
  t = tessellate({square}, grid, cpu);
  const std::vector<double> small{0.01}, large{1.0};
  CHECK(findResultWarnings(t, {square}, &small).empty());
  w = findResultWarnings(t, {square}, &large);
  REQUIRE(w.size() == 1);
  CHECK(w[0].code == "large-deviation");
}
