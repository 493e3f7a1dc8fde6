// TessellatorOptions::threads (include/tessera/tessera.h): threads = 1 gives the mesh of all
// cores, bit for bit, and runs nothing on a worker thread.
#include <tessera/tessera.h>

#include <catch2/catch.hpp>

#include "common/thread_cap.h"
#include "common/worker_pool.h"
#include "vector_difference.h"

namespace {

const std::string kTeapot = std::string(TESSERA_SOURCE_DIR) + "/data/teapot.bpt";

void requireSameMesh(const tessera::Mesh& a, const tessera::Mesh& b) {
  REQUIRE(tessera::test::vectorDifference(a.positions, b.positions) == "");
  REQUIRE(tessera::test::vectorDifference(a.indices, b.indices) == "");
  REQUIRE(tessera::test::vectorDifference(a.normals, b.normals) == "");
}

}  // namespace

TEST_CASE("public API: threads = 1 is the mesh of all cores, and no worker ran a part",
          "[api][threads]") {
  const std::vector<tessera::Patch> teapot = tessera::loadPatches(kTeapot);
  tessera::TessellatorOptions allCores;
  allCores.device = tessera::Device::Cpu;
  tessera::TessellatorOptions oneThread = allCores;
  oneThread.threads = 1;
  tessera::Tessellator wide(allCores), narrow(oneThread);
  const double tolerance = tessera::relativeTolerance(teapot, 1e-3);
  tessera::RuleOptions ruleB;
  ruleB.rule = tessera::Rule::B;

  const tessera::Mesh wideT = wide.tessellateToTolerance(teapot, tolerance);
  const tessera::Mesh wideB = wide.tessellate(teapot, ruleB);
  const tessera::Mesh wideView = wide.tessellateToPixelTolerance(
      teapot, 1.0, tessera::lookAtView({0, -8, 4}, {0, 0, 1}, {0, 0, 1}, 45, 1920, 1080, 0.1, 100));

  const size_t workerPartsBefore = tessera::worker_pool::partsRunByWorkers();
  const tessera::Mesh narrowT = narrow.tessellateToTolerance(teapot, tolerance);
  const tessera::Mesh narrowB = narrow.tessellate(teapot, ruleB);
  const tessera::Mesh narrowView = narrow.tessellateToPixelTolerance(
      teapot, 1.0, tessera::lookAtView({0, -8, 4}, {0, 0, 1}, {0, 0, 1}, 45, 1920, 1080, 0.1, 100));
  REQUIRE(tessera::worker_pool::partsRunByWorkers() == workerPartsBefore);
  REQUIRE(tessera::threadCap() == 0);  // the call's cap ends with it

  requireSameMesh(narrowT, wideT);
  requireSameMesh(narrowB, wideB);
  requireSameMesh(narrowView, wideView);
}
