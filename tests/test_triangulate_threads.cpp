// triangulateLeaves walks runs of leaves on several threads and numbers their vertices after
// (TriangulationScope::threads): the mesh must not depend on the thread count. On the tea set's
// quad-trees (rule C at 0.1 merges near points, rule T at 0.01% is deep), whole and in a
// streamed group's scope (leaves outside it walked without triangles, seam keys).
#include <catch2/catch.hpp>

#include <string>

#include "geometry/model_frame.h"
#include "io/bpt_reader.h"
#include "mesh/shared_edges.h"
#include "mesh/tessellate.h"
#include "mesh/triangulate.h"
#include "quadtree/tolerance.h"

using namespace tessera;

namespace {

void requireSameMesh(const ParamMesh& a, const ParamMesh& b) {
  REQUIRE(a.vertices.size() == b.vertices.size());
  for (size_t i = 0; i < a.vertices.size(); ++i) {
    INFO("vertex " << i);
    REQUIRE(a.vertices[i].patchIndex == b.vertices[i].patchIndex);
    REQUIRE(a.vertices[i].u == b.vertices[i].u);
    REQUIRE(a.vertices[i].v == b.vertices[i].v);
  }
  REQUIRE(a.indices == b.indices);
  REQUIRE(a.trianglePatch == b.trianglePatch);
  REQUIRE(a.cornerUv == b.cornerUv);
  REQUIRE(a.droppedTriangles == b.droppedTriangles);
  REQUIRE(a.diagonalFans == b.diagonalFans);
  REQUIRE(a.seamKeys.size() == b.seamKeys.size());
  for (size_t i = 0; i < a.seamKeys.size(); ++i) {
    INFO("seam key " << i);
    REQUIRE(a.seamKeys[i].kind == b.seamKeys[i].kind);
    REQUIRE(a.seamKeys[i].group == b.seamKeys[i].group);
    REQUIRE(a.seamKeys[i].parameter == b.seamKeys[i].parameter);
    REQUIRE(a.seamKeys[i].point == b.seamKeys[i].point);
  }
}

}  // namespace

TEST_CASE("triangulation: the same mesh on 1, 3 and all threads", "[triangulate][mesh]") {
  Backend mirror = makeMirrorBackend();
  for (const char* model : {"teapot", "teacup", "teaspoon"}) {
    const std::vector<BezierPatch> patches =
        readBpt(std::string(TESSERA_SOURCE_DIR "/data/") + model + ".bpt");
    const std::vector<BezierPatch> local = toLocalFrame(patches, modelFrame(patches));
    const PatchTopology topology = findSharedEdges(local);
    QuadtreeOptions ruleC;
    ruleC.rule = SplitRule::SampledMax;
    ruleC.flatness = ruleC.linearity = 0.1f;
    const QuadtreeOptions ruleT =
        toleranceOptions(resolveTolerance(parseTolerance("0.01%"), patches));
    for (const QuadtreeOptions& options : {ruleC, ruleT}) {
      const std::vector<QuadLeaf> leaves = tessellate(patches, options, mirror).tree.leaves;
      INFO(model << ", rule " << splitRuleLetter(options.rule) << ": " << leaves.size()
                 << " leaves");
      // Several runs of leaves (512 each) to share out.
      REQUIRE(leaves.size() > 4 * 512);
      TriangulationScope whole, group;
      group.topology = &topology;
      group.firstPatch = 0;
      group.endPatch = uint32_t(local.size() / 2);
      group.seamKeys = true;
      for (TriangulationScope scope : {whole, group}) {
        scope.threads = 1;
        const ParamMesh one = triangulateLeaves(leaves, local, scope);
        REQUIRE(one.indices.size() > 3 * leaves.size() / 2);
        for (unsigned threads : {3u, 0u}) {
          INFO(threads << " threads (0: all), scope " << scope.endPatch);
          scope.threads = threads;
          requireSameMesh(one, triangulateLeaves(leaves, local, scope));
        }
      }
    }
  }
}
