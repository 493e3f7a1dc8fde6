// Real-time view-dependent tessellation (host/realtime/frame.h): on a few frames of two
// teapots the stitched meshes meet 1 px on screen (measured against the double surface) with
// the estimated counts and with the proven ones (fewer triangles with the estimate), their
// vertices and indices are the pattern's fp32 mirror bit for bit, a finer tolerance spends more
// triangles, a camera inside the scene routes eye-plane patches to the clipped host count, and
// looking away culls everything.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

#include "eval/evaluator.h"
#include "gpu_test_context.h"
#include "io/bpt_reader.h"
#include "realtime/frame.h"
#include "frame_difference.h"

using namespace tessera;

namespace {

std::vector<BezierPatch> twoTeapots() {
  std::vector<BezierPatch> scene = readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt");
  const size_t n = scene.size();
  for (size_t p = 0; p < n; ++p) {
    BezierPatch copy = scene[p];
    for (glm::dvec3& c : copy.cp) c += glm::dvec3(8.0, 0.0, 0.0);
    scene.push_back(copy);
  }
  return scene;
}

Camera view(const glm::dvec3& eye, const glm::dvec3& target) {
  return lookAtCamera(eye, target, {0, 0, 1}, 0.8, 640, 360, 0.05, 200.0);
}

// The frame's vertices and indices against the fp32 mirror's pattern, bit for bit: the number
// of differing vertices plus differing indices.
test::FrameDifference differenceFromMirror(const RealtimeTessellator& tessellator,
                                           const RealtimeFrame& frame) {
  std::vector<gpu::GridVertex> vertices;
  std::vector<uint32_t> indices;
  tessellator.mirrorLastFrame(vertices, indices);
  REQUIRE(vertices.size() <= frame.vertexCount);
  REQUIRE(indices.size() <= 3 * frame.triangles);
  return test::frameDifference(frame.vertices, frame.indices, vertices.data(),
                               indices.data(), vertices.size(), indices.size());
}

// The mirror's frame bit for bit on lavapipe; elsewhere its indices, and positions within the
// band of fused multiply-adds.
void checkAgainstMirror(const RealtimeTessellator& tessellator, const RealtimeFrame& frame) {
  const test::FrameDifference d = differenceFromMirror(tessellator, frame);
  INFO("against the mirror: " << d.vertices << " vertices, " << d.indices
                              << " indices differ (largest " << d.largest << ")");
  if (test::exactMirrorArithmetic()) {
    CHECK(d.vertices + d.indices == 0);
  } else {
    CHECK(d.indices == 0);
    CHECK(d.largest <= test::kFusedPositionBand);
  }
}

// Vertices whose normal is not a unit vector, and the frame's collapsed sides (poles): there
// every normal comes from bicubicNormal's full rule, which the pattern runs in a last loop
// over the degenerate points (shaders/stitch_pattern.comp.glsl); a point that loop missed
// keeps the vertex loop's zero.
size_t nonUnitNormals(const RealtimeFrame& frame) {
  size_t bad = 0;
  for (size_t v = 0; v < frame.vertexCount; ++v) {
    const gpu::vec4& n = frame.vertices[v].normal;
    bad += !(std::abs(std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z) - 1.0f) < 1e-5f);
  }
  return bad;
}

// Patches drawn by more than one work item (more inner rows than a band of the pattern holds).
size_t patchesInSeveralBands(const RealtimeFrame& frame) {
  size_t patches = 0;
  for (const gpu::StitchPatch& record : frame.records)
    patches += record.nu > gpu::kStitchBandRows + 1;  // inner rows: N_u − 1
  return patches;
}

size_t collapsedSides(const RealtimeFrame& frame) {
  size_t sides = 0;
  for (const gpu::StitchPatch& record : frame.records)
    for (int s = 0; s < 4; ++s) sides += (record.sideFlags[s] & gpu::kStitchCollapsed) != 0;
  return sides;
}

}  // namespace

TEST_CASE("Real-time frames meet 1 px on screen and match the mirror", "[gpu][realtime]") {
  vk::Context& context = test::gpuContext();
  const std::vector<BezierPatch> scene = twoTeapots();
  RealtimeOptions estimated{1.0, 64}, proven = estimated;
  proven.counts = RealtimeCounts::Proven;
  RealtimeTessellator tessellator(context, scene, estimated), provenTessellator(context, scene, proven);
  const std::vector<std::pair<const char*, Camera>> cameras = {
      {"overview", view({4, -14, 6}, {4, 0, 1.5})},
      {"close", view({1.5, -4, 2.5}, {0, 0, 1.5})},
      {"inside the second teapot", view({8, 0, 1.5}, {0, 0, 1.5})},
  };
  size_t estimatedTriangles = 0, provenTriangles = 0, polesSeen = 0, banded = 0;
  for (const auto& [name, camera] : cameras) {
    // The proven counts (host/division/projected.h) on the same view: within 1 px too.
    const RealtimeFrame& provenFrame = provenTessellator.tessellate(camera);
    const ScreenErrorReport provenError = measureScreenError(provenFrame, scene, camera, 2);
    provenTriangles += provenFrame.triangles;
    WARN(name << " with proven counts: " << provenFrame.triangles << " triangles, max error "
              << provenError.maxAffinePixels << " px (affine), "
              << provenError.maxPerspectivePixels << " px (perspective)");
    CHECK(provenError.maxAffinePixels <= 1.0);
    CHECK(provenError.maxPerspectivePixels <= 1.0);
    checkAgainstMirror(provenTessellator, provenFrame);

    const RealtimeFrame& frame = tessellator.tessellate(camera);
    estimatedTriangles += frame.triangles;
    const ScreenErrorReport error = measureScreenError(frame, scene, camera, 2);
    INFO(name << ": " << frame.records.size() << " patches, " << frame.triangles << " triangles, "
              << frame.culled << " culled, " << frame.fallback << " eye-plane fallbacks, "
              << frame.capped << " capped; max error " << error.maxAffinePixels
              << " px affine, " << error.maxPerspectivePixels << " px perspective over "
              << error.triangles << " triangles");
    WARN(name << ": " << frame.triangles << " triangles, max error " << error.maxAffinePixels
              << " px (affine), " << error.maxPerspectivePixels << " px (perspective), "
              << frame.fallback << " eye-plane fallbacks");
    CHECK(frame.records.size() > 0);
    CHECK(error.triangles > 0);
    CHECK(frame.capped == 0);
    CHECK(error.maxAffinePixels <= 1.0);
    CHECK(error.maxPerspectivePixels <= 1.0);
    checkAgainstMirror(tessellator, frame);
    CHECK(nonUnitNormals(frame) == 0);
    polesSeen += collapsedSides(frame);
    banded += patchesInSeveralBands(frame) + patchesInSeveralBands(provenFrame);
    if (std::string(name) == "inside the second teapot") CHECK(frame.fallback > 0);
  }
  CHECK(polesSeen > 0);  // the lids' and bottoms' poles were drawn: the degenerate loop ran
  CHECK(banded > 0);     // and patches split into several work items
  // The estimate (the default) needs far fewer triangles than the bound for the same views.
  CHECK(estimatedTriangles < 0.8 * provenTriangles);
  test::requireValidationClean();
}

TEST_CASE("Real-time frames: finer tolerance costs triangles, looking away culls all",
          "[gpu][realtime]") {
  vk::Context& context = test::gpuContext();
  const std::vector<BezierPatch> scene = twoTeapots();
  RealtimeTessellator coarse(context, scene, {4.0, 64}), fine(context, scene, {0.25, 64});
  const Camera camera = view({4, -14, 6}, {4, 0, 1.5});
  const size_t coarseTriangles = coarse.tessellate(camera).triangles;
  const size_t fineTriangles = fine.tessellate(camera).triangles;
  WARN("4 px: " << coarseTriangles << " triangles, 0.25 px: " << fineTriangles);
  CHECK(fineTriangles > 4 * coarseTriangles);
  const RealtimeFrame& away = coarse.tessellate(view({4, -14, 6}, {4, -40, 6}));
  CHECK(away.records.empty());
  CHECK(away.culled == scene.size());
  CHECK(away.triangles == 0);
  CHECK_THROWS_AS(RealtimeTessellator(context, scene, {0.0, 64}), std::invalid_argument);
  test::requireValidationClean();
}
