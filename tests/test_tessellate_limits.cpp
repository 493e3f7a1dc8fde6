// What tessellate() does with shapes and settings that could run away or poison the output:
// a documented safe result or a clear error, never a crash, a NaN or an exhausted machine.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "io/bpt_reader.h"
#include "mesh/tessellate.h"

using namespace tessera;

namespace {

BezierPatch pointPatch() {  // every control point equal: a patch collapsed to a point
  BezierPatch p;
  p.cp.assign(16, glm::dvec3(1.0, 2.0, 3.0));
  return p;
}

}  // namespace

TEST_CASE("runaway refinement stops at the node budget, naming the patch and level",
          "[tessellate][limits]") {
  auto teapot = readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt");
  Backend cpu = makeMirrorBackend();
  QuadtreeOptions o;
  o.linearity = o.flatness = 1e-6f;  // practically never flat
  o.nodeBudget = 5000;
  REQUIRE_THROWS_AS(tessellate(teapot, o, cpu), TessellationLimitError);
  REQUIRE_THROWS_WITH(tessellate(teapot, o, cpu),
                      Catch::Contains("node budget of 5000") && Catch::Contains("patch ") &&
                          Catch::Contains("level ") && Catch::Contains("Raise the thresholds"));
}

TEST_CASE("rule T at the node budget says to raise the tolerance", "[tessellate][limits][tolerance]") {
  auto teapot = readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt");
  Backend cpu = makeMirrorBackend();
  QuadtreeOptions o = toleranceOptions(1e-6);
  o.nodeBudget = 5000;
  REQUIRE_THROWS_WITH(tessellate(teapot, o, cpu), Catch::Contains("node budget of 5000") &&
                                                      Catch::Contains("Raise the tolerance") &&
                                                      !Catch::Contains("thresholds"));
}

TEST_CASE("the maximum depth bounds refinement, and every leaf records why it ended",
          "[tessellate][limits]") {
  auto teapot = readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt");
  Backend cpu = makeMirrorBackend();
  QuadtreeOptions o;
  o.linearity = o.flatness = 1e-6f;
  o.maxDepth = 3;
  Tessellation t = tessellate(teapot, o, cpu);
  REQUIRE(t.stats.depth == 3);
  size_t atDepth = 0;
  for (const QuadLeaf& leaf : t.tree.leaves) {
    REQUIRE(leaf.level <= 3);
    REQUIRE(leaf.cause != gpu::kCauseSplit);
    if (leaf.cause == gpu::kCauseMaxDepth) ++atDepth;
  }
  REQUIRE(atDepth > 0);
}

TEST_CASE("a patch collapsed to a point gives one leaf and no triangles, never NaN",
          "[tessellate][limits]") {
  Backend cpu = makeMirrorBackend();
  for (SplitRule rule : {SplitRule::Midpoint, SplitRule::SampledMax, SplitRule::TrueMax}) {
    QuadtreeOptions o;
    o.rule = rule;
    Tessellation t = tessellate({pointPatch()}, o, cpu);
    REQUIRE(t.tree.leaves.size() == 1);
    REQUIRE(t.mesh.triangleCount() == 0);
    for (const auto& n : t.mesh.normals) REQUIRE(std::isfinite(n.x + n.y + n.z));
  }
}

TEST_CASE("non-finite or huge control points are refused with the patch named",
          "[tessellate][limits]") {
  Backend cpu = makeMirrorBackend();
  QuadtreeOptions o;
  BezierPatch bad = pointPatch();
  bad.cp[5].y = std::numeric_limits<double>::quiet_NaN();
  REQUIRE_THROWS_WITH(tessellate({pointPatch(), bad}, o, cpu), Catch::Contains("patch 1"));
  bad.cp[5].y = 1e300;
  REQUIRE_THROWS_AS(tessellate({bad}, o, cpu), std::invalid_argument);
  BezierPatch octic;
  octic.degreeU = 8;
  octic.degreeV = 2;
  octic.cp.assign(27, glm::dvec3(0.0));
  REQUIRE_THROWS_WITH(tessellate({octic}, o, cpu), Catch::Contains("degrees 1..7"));
  BezierPatch weighted = pointPatch();
  weighted.weights.assign(16, 1.0);
  weighted.weights[5] = -1.0;
  REQUIRE_THROWS_WITH(tessellate({weighted}, o, cpu), Catch::Contains("negative"));
  weighted.weights[5] = 1.0;
  weighted.weights[15] = 0.0;
  REQUIRE_THROWS_WITH(tessellate({weighted}, o, cpu), Catch::Contains("corner weight"));
}

TEST_CASE("bad options are refused with the reason", "[tessellate][limits]") {
  Backend cpu = makeMirrorBackend();
  QuadtreeOptions o;
  o.flatness = std::numeric_limits<float>::quiet_NaN();
  REQUIRE_THROWS_WITH(tessellate({pointPatch()}, o, cpu), Catch::Contains("flatness"));
  o = QuadtreeOptions{};
  o.maxDepth = 40;
  REQUIRE_THROWS_WITH(tessellate({pointPatch()}, o, cpu), Catch::Contains("maximum depth"));
  o = QuadtreeOptions{};
  o.samples = 0;
  REQUIRE_THROWS_AS(tessellate({pointPatch()}, o, cpu), std::invalid_argument);
}
