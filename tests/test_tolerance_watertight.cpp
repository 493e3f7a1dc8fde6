// Rule T's meshes of the tea set are watertight: at δ = 1%, 0.1% and 0.01% of each model's
// control-point diagonal, whatever mix of u, v and both-way splits the bound chose, every edge
// is shared by exactly two consistently oriented triangles except along patch sides no other
// patch shares (the models' true open boundaries), no vertex lies inside another triangle's
// open edge (T-junction), no edge is used three times, and no triangle has zero area.
// The teaspoon too: its handle tip's side that folds back on itself (patch 12, u = 1) is zipped
// to itself (side_fold.h; it had 1, 3 and 10 T-junctions at these δ before).
#include <catch2/catch.hpp>

#include <string>

#include "io/bpt_reader.h"
#include "mesh/shared_edges.h"
#include "mesh/tessellate.h"
#include "tessellation_defects.h"
#include "quadtree/tolerance.h"

using namespace tessera;

namespace {

void requireWatertightTeaSetModel(const std::string& model) {
  const std::vector<BezierPatch> patches =
      readBpt(std::string(TESSERA_SOURCE_DIR "/data/") + model + ".bpt");
  const PatchTopology topology = findSharedEdges(patches);
  const double diagonal = controlPointDiagonal(patches);
  Backend cpu = makeMirrorBackend();
  for (const char* given : {"1%", "0.1%", "0.01%"}) {
    QuadtreeOptions o = toleranceOptions(resolveTolerance(parseTolerance(given), patches));
    const Tessellation t = tessellate(patches, o, cpu);
    // A T-junction's vertex lies on the neighbour's edge up to fp32 rounding of the positions.
    const test::WatertightCounts n = test::countDefects(t, topology, 1e-6 * diagonal);
    WARN(model << " at δ " << given << " = " << o.tolerance << ": " << n.triangles
               << " triangles, cracks " << n.cracks << ", T-junctions " << n.tJunctions
               << " (longest such edge " << n.largestTJunctionEdge << "), over-used edges "
               << n.overused << ", inconsistent " << n.inconsistent << ", zero-area "
               << n.degenerate);
    REQUIRE(n.triangles > 0);
    CHECK(n.cracks == 0);
    CHECK(n.tJunctions == 0);
    CHECK(n.overused == 0);
    CHECK(n.inconsistent == 0);
    CHECK(n.degenerate == 0);
  }
}

}  // namespace

TEST_CASE("rule T: the teapot is watertight at 1%, 0.1% and 0.01% of its size",
          "[watertight][tolerance]") {
  requireWatertightTeaSetModel("teapot");
}

TEST_CASE("rule T: the teacup is watertight at 1%, 0.1% and 0.01% of its size",
          "[watertight][tolerance]") {
  requireWatertightTeaSetModel("teacup");
}

TEST_CASE("rule T: the teaspoon is watertight at 1%, 0.1% and 0.01% of its size",
          "[watertight][tolerance]") {
  requireWatertightTeaSetModel("teaspoon");
}
