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
#include "param_mesh_compare.h"
#include "quadtree/tolerance.h"

using namespace tessera;

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
          test::requireSameParamMesh(one, triangulateLeaves(leaves, local, scope));
        }
      }
    }
  }
}
