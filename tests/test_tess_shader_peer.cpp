// The tessellation-shader peer (host/realtime/tess_shader_peer.h): draws validation-clean, culls what
// is off screen, and its triangle count grows as the tolerance shrinks (the screen-space rule).
#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include "eval/evaluator.h"
#include "gpu_test_context.h"
#include "io/bpt_reader.h"
#include "realtime/tess_shader_peer.h"

using namespace tessera;

TEST_CASE("tessellation-shader peer draws the teapot", "[gpu][tesspeer]") {
  vk::Context& context = test::gpuContext();
  if (!context.enabledFeatures().tessellationShader) {
    FAIL("device " << context.info().name << " has no tessellation shaders");
  }
  auto teapot = toGpuPatches(readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt"));
  glm::mat4 view = glm::lookAtRH(glm::vec3(8, -10, 6), glm::vec3(0, 0, 1.5f), glm::vec3(0, 0, 1));
  glm::mat4 seen = glm::perspectiveRH_ZO(glm::radians(40.0f), 320.0f / 240.0f, 0.1f, 100.0f) * view;
  glm::mat4 away = glm::perspectiveRH_ZO(glm::radians(40.0f), 320.0f / 240.0f, 0.1f, 100.0f) *
                   glm::lookAtRH(glm::vec3(8, -10, 6), glm::vec3(16, -20, 12), glm::vec3(0, 0, 1));
  TessPeerOptions coarse{320, 240, 4.0f, 64.0f}, fine{320, 240, 0.25f, 64.0f};
  TessShaderPeer a(context, teapot, coarse), b(context, teapot, fine);
  uint64_t coarseTriangles = a.drawFrame(seen), fineTriangles = b.drawFrame(seen);
  uint64_t culled = a.drawFrame(away);
  WARN("teapot at 320x240: " << coarseTriangles << " triangles at 4 px, " << fineTriangles
                             << " at 0.25 px, " << culled << " looking away");
  if (a.countsTriangles()) {
    CHECK(coarseTriangles >= 2 * teapot.size());
    CHECK(fineTriangles > 4 * coarseTriangles);
    CHECK(culled == 0);
  }
  test::requireValidationClean();
}
