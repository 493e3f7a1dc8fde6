// The public interop API (include/tessera/vulkan.h): an engine lends its own instance, device
// and queue (tests/engine_device.h: validation with synchronisation checks on its instance).
// A Tessellator on it gives the CPU's mesh; a RealtimeScene records frames into the engine's
// command buffers and buffers that equal the real-time path on Tessera's own device bit for
// bit; bad patches, bad ranges and a device without push descriptors are typed errors.
#define VK_NO_PROTOTYPES  // the engine loads its functions itself, as volk users do
#include <tessera/vulkan.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "api/convert.h"
#include "engine_device.h"
#include "frame_difference.h"
#include "gpu_test_context.h"
#include "realtime/frame.h"

using namespace tessera;
using test::check;
using test::Engine;
using test::EngineBuffer;

namespace {

const std::string kTeapot = TESSERA_SOURCE_DIR "/data/teapot.bpt";

VulkanDevice lent(const Engine& engine) {
  return {engine.instance, engine.physical, engine.device, engine.family, engine.queue};
}

RealtimeFrameTargets targetsOf(const EngineBuffer& buffer) {
  const auto range = [](const test::EngineRange& r) {
    return BufferRange{r.buffer, r.offset, r.size};
  };
  return {range(buffer.targets.vertices), range(buffer.targets.indices),
          range(buffer.targets.drawCommand)};
}

// The teapot three times, moved apart.
std::vector<Patch> threeTeapots() {
  const std::vector<Patch> teapot = loadPatches(kTeapot);
  std::vector<Patch> scene;
  for (int k = 0; k < 3; ++k)
    for (Patch patch : teapot) {
      for (size_t i = 0; i < patch.points.size(); i += 3) {
        patch.points[i] += 7.0 * k;
        patch.points[i + 1] += 2.0 * k;
      }
      scene.push_back(patch);
    }
  return scene;
}

}  // namespace

TEST_CASE("public Vulkan API: the near plane read from a perspective matrix", "[api]") {
  for (double near : {0.05, 0.5, 3.0}) {
    const Camera camera = lookAtCamera({3, -7, 4}, {0, 0, 1}, {0, 0, 1}, 0.8, 640, 360, near, 90);
    CHECK(api::nearPlaneW(camera.viewProjection, -1) == Approx(near).epsilon(1e-9));
  }
  CHECK(api::nearPlaneW(glm::dmat4(1.0), -1) == -1);  // clip z = world z: not a perspective
}

TEST_CASE("public Vulkan API: a Tessellator on an engine's device gives the CPU's mesh",
          "[gpu][api][interop]") {
  Engine engine(test::gpuContext().info().name);
  const std::vector<Patch> teapot = loadPatches(kTeapot);
  {
    Tessellator onEngine = tessellatorOnDevice(lent(engine));
    REQUIRE(onEngine.usesVulkan());
    CHECK(onEngine.deviceName() == engine.deviceName);
    const Mesh mesh = onEngine.tessellateToTolerance(teapot, 0.01);
    const Mesh cpu = Tessellator({Device::Cpu}).tessellateToTolerance(teapot, 0.01);
    float largest = 0;  // the largest position difference where the counts agree
    if (mesh.positions.size() == cpu.positions.size())
      for (size_t k = 0; k < mesh.positions.size(); ++k)
        largest = std::max(largest, std::abs(mesh.positions[k] - cpu.positions[k]));
    INFO("on " << engine.deviceName << ": " << mesh.triangleCount() << " triangles, CPU "
               << cpu.triangleCount() << "; largest position difference " << largest);
    if (test::exactMirrorArithmetic()) {
      CHECK(mesh.indices == cpu.indices);
      CHECK(mesh.positions == cpu.positions);
    } else {
      CHECK(std::abs(double(mesh.triangleCount()) - double(cpu.triangleCount())) <=
            0.01 * double(cpu.triangleCount()));
    }
  }
  TessellatorOptions cpuOnly;
  cpuOnly.device = Device::Cpu;
  CHECK_THROWS_AS(tessellatorOnDevice(lent(engine), cpuOnly), ArgumentError);
  VulkanDevice missing = lent(engine);
  missing.queue = VK_NULL_HANDLE;
  CHECK_THROWS_AS(tessellatorOnDevice(missing), ArgumentError);
  for (const std::string& m : engine.messages) UNSCOPED_INFO(m);
  REQUIRE(engine.messages.empty());
}

TEST_CASE(
    "public Vulkan API: a RealtimeScene records the real-time path's frame into an "
    "engine's buffers",
    "[gpu][api][interop]") {
  Engine engine(test::gpuContext().info().name);
  const std::vector<Patch> scene = threeTeapots();
  const View view = lookAtView({7, -16, 7}, {7, 2, 1.5}, {0, 0, 1}, 45.8366, 640, 360, 0.05, 200);
  // The reference: the internal path on Tessera's own device, its camera as lookAtCamera makes
  // it (the near plane prepare() reads from the matrix).
  RealtimeTessellator reference(test::gpuContext(), api::toBezierPatches(scene));
  Camera camera = api::toCamera(view);
  camera.nearW = api::nearPlaneW(camera.viewProjection, 0.01);
  REQUIRE(camera.nearW == Approx(0.05).epsilon(1e-9));
  const RealtimeFrame& expected = reference.tessellate(camera);
  REQUIRE(expected.triangles > 1000);
  {
    RealtimeScene realtime(lent(engine), scene);
    // Refused before anything is recorded (so no command buffer is needed to see it).
    CHECK_THROWS_WITH(realtime.record(VK_NULL_HANDLE, RealtimeFrameTargets{}),
                      Catch::Contains("no frame prepared"));
    const RealtimeFrameInfo info = realtime.prepare(view);
    CHECK(info.triangles == expected.triangles);
    CHECK(info.vertices == expected.vertexCount);
    CHECK(info.visiblePatches == expected.records.size());
    CHECK(info.culledPatches == expected.culled);
    CHECK(info.vertexBytes == RealtimeScene::kVertexBytes * expected.vertexCount);
    CHECK(info.indexBytes == 4 * 3 * expected.triangles);
    EngineBuffer buffer(engine, info.vertexBytes, info.indexBytes);
    RealtimeFrameTargets wrong = targetsOf(buffer);
    wrong.indices.size -= 4;
    CHECK_THROWS_WITH(realtime.record(VK_NULL_HANDLE, wrong),
                      Catch::Contains("the frame needs " + std::to_string(info.indexBytes)));
    CHECK_THROWS_AS(realtime.record(VK_NULL_HANDLE, wrong), ArgumentError);
    if (engine.storageAlignment > 1) {
      wrong = targetsOf(buffer);
      wrong.vertices.offset += 1;
      CHECK_THROWS_WITH(realtime.record(VK_NULL_HANDLE, wrong),
                        Catch::Contains("minStorageBufferOffsetAlignment"));
    }
    test::submitOnce(engine, [&](VkCommandBuffer cmd) { realtime.record(cmd, targetsOf(buffer)); });
    const auto* draw = buffer.at<VkDrawIndexedIndirectCommand>(buffer.targets.drawCommand);
    CHECK(draw->indexCount == 3 * expected.triangles);
    CHECK(draw->instanceCount == 1);
    const test::FrameDifference difference =
        test::frameDifference(buffer.at<gpu::GridVertex>(buffer.targets.vertices),
                              buffer.at<uint32_t>(buffer.targets.indices), expected.vertices,
                              expected.indices, expected.vertexCount, 3 * expected.triangles);
    INFO(difference.vertices << " vertices and " << difference.indices
                             << " indices differ from the path on Tessera's device (largest "
                             << "position difference " << difference.largest << ")");
    CHECK(difference.vertices + difference.indices == 0);

    // A view of nothing (looking away): no triangles, and the draw command says so.
    const RealtimeFrameInfo away = realtime.prepare(
        lookAtView({7, -16, 7}, {7, -40, 7}, {0, 0, 1}, 45.8366, 640, 360, 0.05, 200));
    CHECK(away.triangles == 0);
    CHECK(away.visiblePatches == 0);
    CHECK(away.culledPatches == scene.size());
    test::submitOnce(engine, [&](VkCommandBuffer cmd) { realtime.record(cmd, targetsOf(buffer)); });
    CHECK(draw->indexCount == 0);
  }

  // Patches the path cannot take, and a device without push descriptors.
  std::vector<Patch> quadratic = {Patch{}};
  quadratic[0].degreeU = quadratic[0].degreeV = 2;
  quadratic[0].points.assign(27, 0.0);
  for (int k = 0; k < 9; ++k) quadratic[0].points[size_t(3 * k)] = k;
  CHECK_THROWS_WITH(RealtimeScene(lent(engine), quadratic),
                    Catch::Contains("bicubic patches only"));
  std::vector<Patch> rational = {scene[0]};
  rational[0].weights.assign(16, 1.0);
  rational[0].weights[5] = 2.0;
  CHECK_THROWS_WITH(RealtimeScene(lent(engine), rational), Catch::Contains("is rational"));
  rational[0].weights[5] = 1.0;  // weights all 1: polynomial
  CHECK_NOTHROW(RealtimeScene(lent(engine), rational));
  VulkanDevice bare = lent(engine);
  bare.device = engine.createDevice({});
  CHECK_THROWS_WITH(RealtimeScene(bare, scene),
                    Catch::Contains(VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME));
  reinterpret_cast<PFN_vkDestroyDevice>(engine.vkGetDeviceProcAddr(bare.device, "vkDestroyDevice"))(
      bare.device, nullptr);
  for (const std::string& m : engine.messages) UNSCOPED_INFO(m);
  REQUIRE(engine.messages.empty());
  test::requireValidationClean();
}
