// Engine interop (host/realtime/frame_record_vulkan.h, vk::ExternalDevice): the test makes its own
// instance and device as an engine would (its own loader handle, validation with
// synchronisation checks, its own messenger), borrows them for a Tessera context, records
// frames into its own command buffers and buffers, submits with its own fence, and requires
// the vertices, indices and draw command to equal the real-time path's own (Tessera's device,
// tessellate()) and the fp32 mirror bit for bit. Then the context is destroyed and the device
// must still work; a device without VK_KHR_push_descriptor is refused by name.
#define VK_NO_PROTOTYPES  // the engine loads its functions itself, as volk users do
#include <vulkan/vulkan.h>

#include <dlfcn.h>

#include <catch2/catch.hpp>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "gpu_test_context.h"
#include "io/bpt_reader.h"
#include "realtime/frame_record_vulkan.h"
#include "vk/context.h"
#include "engine_device.h"
#include "frame_difference.h"

using namespace tessera;
using test::check;
using test::Engine;
using test::EngineBuffer;

namespace {

vk::ExternalDevice external(const Engine& engine) {
  return {engine.instance, engine.physical, engine.device, engine.family, engine.queue};
}

RealtimeTargets targetsOf(const EngineBuffer& buffer) {
  const auto range = [](const test::EngineRange& r) {
    return DeviceBufferRange{r.buffer, r.offset, r.size};
  };
  return {range(buffer.targets.vertices), range(buffer.targets.indices),
          range(buffer.targets.drawCommand)};
}

std::vector<BezierPatch> threeTeapots() {
  const std::vector<BezierPatch> teapot = readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt");
  std::vector<BezierPatch> scene;
  for (int k = 0; k < 3; ++k)
    for (BezierPatch patch : teapot) {
      for (glm::dvec3& c : patch.cp) c += glm::dvec3(7.0 * k, 2.0 * k, 0.0);
      scene.push_back(patch);
    }
  return scene;
}

Camera view(const glm::dvec3& eye, const glm::dvec3& target) {
  return lookAtCamera(eye, target, {0, 0, 1}, 0.8, 640, 360, 0.05, 200.0);
}

// Vertices and indices that differ from the reference frame, bit for bit, plus the largest
// position difference seen (for the failure message).

}  // namespace

TEST_CASE("Real-time frames recorded into an engine's command buffer and buffers",
          "[gpu][realtime][interop]") {
  const std::string deviceName = test::gpuContext().info().name;
  Engine engine(deviceName);
  INFO("engine device: " << engine.deviceName);
  const std::vector<BezierPatch> scene = threeTeapots();
  // The existing path, on Tessera's own device: the reference.
  RealtimeTessellator reference(test::gpuContext(), scene);
  const std::vector<std::pair<const char*, Camera>> cameras = {
      {"overview", view({7, -16, 7}, {7, 2, 1.5})},
      {"close, cut by the frustum", view({1.5, -4, 2.5}, {0, 0, 1.5})},
  };
  {
    vk::Context context(external(engine));
    CHECK_FALSE(context.ownsDevice());
    CHECK(context.info().name == engine.deviceName);
    RealtimeTessellator tessellator(context, scene);
    RealtimeRecorder recorder(tessellator, 2);

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.queueFamilyIndex = engine.family;
    VkCommandPool pool = VK_NULL_HANDLE;
    check(engine.vkCreateCommandPool(engine.device, &poolInfo, nullptr, &pool), "pool");
    VkCommandBuffer commands[2] = {};
    VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocInfo.commandPool = pool;
    allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocInfo.commandBufferCount = 2;
    check(engine.vkAllocateCommandBuffers(engine.device, &allocInfo, commands), "command buffers");
    VkFence fence = VK_NULL_HANDLE;
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    check(engine.vkCreateFence(engine.device, &fenceInfo, nullptr, &fence), "fence");

    // Two frames in flight: both recorded (ring slots 0 and 1) before either is submitted.
    std::vector<std::unique_ptr<EngineBuffer>> buffers;
    std::vector<size_t> triangles;
    for (size_t f = 0; f < cameras.size(); ++f) {
      const RealtimeFrame& frame = recorder.prepare(cameras[f].second);
      REQUIRE(frame.vertices == nullptr);
      triangles.push_back(frame.triangles);
      buffers.push_back(std::make_unique<EngineBuffer>(engine, RealtimeRecorder::vertexBytes(frame),
                                                       RealtimeRecorder::indexBytes(frame)));
      VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
      begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
      check(engine.vkBeginCommandBuffer(commands[f], &begin), "begin");
      recorder.record(commands[f], targetsOf(*buffers.back()));
      test::toHostBarrier(engine, commands[f]);
      check(engine.vkEndCommandBuffer(commands[f]), "end");
    }
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 2;
    submit.pCommandBuffers = commands;
    check(engine.vkQueueSubmit(engine.queue, 1, &submit, fence), "submit");
    check(engine.vkWaitForFences(engine.device, 1, &fence, VK_TRUE, UINT64_MAX), "wait");

    for (size_t f = 0; f < cameras.size(); ++f) {
      INFO("camera: " << cameras[f].first);
      const EngineBuffer& buffer = *buffers[f];
      const RealtimeFrame& expected = reference.tessellate(cameras[f].second);
      REQUIRE(expected.triangles == triangles[f]);
      REQUIRE(expected.triangles > 1000);
      const auto* draw = buffer.at<VkDrawIndexedIndirectCommand>(buffer.targets.drawCommand);
      CHECK(draw->indexCount == 3 * expected.triangles);
      CHECK(draw->instanceCount == 1);
      CHECK((draw->firstIndex == 0 && draw->vertexOffset == 0 && draw->firstInstance == 0));
      const auto* vertices = buffer.at<gpu::GridVertex>(buffer.targets.vertices);
      const auto* indices = buffer.at<uint32_t>(buffer.targets.indices);
      const test::FrameDifference fromPath =
          test::frameDifference(vertices, indices, expected.vertices, expected.indices, expected.vertexCount,
                      3 * expected.triangles);
      std::vector<gpu::GridVertex> mirrorVertices;
      std::vector<uint32_t> mirrorIndices;
      reference.mirrorLastFrame(mirrorVertices, mirrorIndices);
      const test::FrameDifference fromMirror =
          test::frameDifference(vertices, indices, mirrorVertices.data(), mirrorIndices.data(),
                      expected.vertexCount, 3 * expected.triangles);
      INFO(expected.vertexCount << " vertices, " << expected.triangles << " triangles; against "
                                << "tessellate(): " << fromPath.vertices << " vertices, "
                                << fromPath.indices << " indices differ (largest "
                                << fromPath.largest
                                << "); against the mirror: " << fromMirror.vertices << ", "
                                << fromMirror.indices << " (largest " << fromMirror.largest << ")");
      CHECK(fromPath.vertices + fromPath.indices == 0);
      if (test::exactMirrorArithmetic()) {
        CHECK(fromMirror.vertices + fromMirror.indices == 0);
      } else {
        CHECK(fromMirror.indices == 0);
        CHECK(fromMirror.largest <= test::kFusedPositionBand);
      }
    }
    engine.vkDestroyFence(engine.device, fence, nullptr);
    engine.vkDestroyCommandPool(engine.device, pool, nullptr);
  }  // the context (and its pipelines, buffers, pool, fence) is gone; the device is not

  // The device still works: fill a buffer and read it back.
  {
    EngineBuffer buffer(engine, 64, 64);
    test::submitOnce(engine, [&](VkCommandBuffer cmd) {
      engine.vkCmdFillBuffer(cmd, buffer.buffer, buffer.targets.indices.offset, 64, 0x7e55e7a);
    });
    CHECK(buffer.at<uint32_t>(buffer.targets.indices)[15] == 0x7e55e7au);
  }

  // A device made without push descriptors is refused, naming the extension.
  VkDevice bare = engine.createDevice({});
  try {
    vk::Context refused(
        vk::ExternalDevice{engine.instance, engine.physical, bare, engine.family, engine.queue});
    FAIL("a device without VK_KHR_push_descriptor was accepted");
  } catch (const vk::VulkanUnavailable& e) {
    CHECK_THAT(e.what(), Catch::Contains(VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME));
  }
  auto destroyBare =
      reinterpret_cast<PFN_vkDestroyDevice>(engine.vkGetDeviceProcAddr(bare, "vkDestroyDevice"));
  destroyBare(bare, nullptr);

  for (const std::string& m : engine.messages) UNSCOPED_INFO(m);
  REQUIRE(engine.messages.empty());
  test::requireValidationClean();
}
