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
#include "frame_difference.h"

using namespace tessera;

namespace {

#define ENGINE_INSTANCE_FUNCTIONS(X)                                                     \
  X(vkDestroyInstance)                                                                   \
  X(vkEnumeratePhysicalDevices) X(vkGetPhysicalDeviceProperties)                         \
      X(vkGetPhysicalDeviceQueueFamilyProperties) X(vkGetPhysicalDeviceMemoryProperties) \
          X(vkCreateDevice) X(vkGetDeviceProcAddr) X(vkCreateDebugUtilsMessengerEXT)     \
              X(vkDestroyDebugUtilsMessengerEXT)
#define ENGINE_DEVICE_FUNCTIONS(X)                                                                 \
  X(vkDestroyDevice)                                                                               \
  X(vkGetDeviceQueue) X(vkDeviceWaitIdle) X(vkCreateCommandPool) X(vkDestroyCommandPool)           \
      X(vkAllocateCommandBuffers) X(vkBeginCommandBuffer) X(vkEndCommandBuffer) X(vkQueueSubmit)   \
          X(vkCreateFence) X(vkDestroyFence) X(vkWaitForFences) X(vkResetFences) X(vkCreateBuffer) \
              X(vkDestroyBuffer) X(vkGetBufferMemoryRequirements) X(vkAllocateMemory)              \
                  X(vkFreeMemory) X(vkBindBufferMemory) X(vkMapMemory) X(vkCmdPipelineBarrier)     \
                      X(vkCmdFillBuffer) X(vkResetCommandPool)
#define ENGINE_MEMBER(name) PFN_##name name = nullptr;

VKAPI_ATTR VkBool32 VKAPI_CALL collectMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                              VkDebugUtilsMessageTypeFlagsEXT,
                                              const VkDebugUtilsMessengerCallbackDataEXT* data,
                                              void* user) {
  static_cast<std::vector<std::string>*>(user)->push_back(data && data->pMessage ? data->pMessage
                                                                                 : "(no text)");
  return VK_FALSE;
}

void check(VkResult result, const char* what) {
  if (result != VK_SUCCESS) FAIL(what << " failed: VkResult " << int(result));
}

// What an engine holds: its instance (validation on, messages collected), the physical device
// Tessera's shared test context chose (same name), one graphics + compute queue, its device.
struct Engine {
  PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr;
  ENGINE_INSTANCE_FUNCTIONS(ENGINE_MEMBER)
  ENGINE_DEVICE_FUNCTIONS(ENGINE_MEMBER)
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  std::string deviceName;
  VkPhysicalDeviceMemoryProperties memory{};
  VkDeviceSize storageAlignment = 1;
  uint32_t family = UINT32_MAX;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  std::vector<std::string> messages;

  explicit Engine(const std::string& wantedDevice) {
    void* library = dlopen("libvulkan.so.1", RTLD_NOW | RTLD_LOCAL);
    REQUIRE(library);
    getInstanceProcAddr =
        reinterpret_cast<PFN_vkGetInstanceProcAddr>(dlsym(library, "vkGetInstanceProcAddr"));
    REQUIRE(getInstanceProcAddr);
    auto createInstance = reinterpret_cast<PFN_vkCreateInstance>(
        getInstanceProcAddr(VK_NULL_HANDLE, "vkCreateInstance"));
    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{
        VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messengerInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                    VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messengerInfo.pfnUserCallback = collectMessage;
    messengerInfo.pUserData = &messages;
    VkValidationFeatureEnableEXT enables[] = {
        VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = enables;
    features.pNext = &messengerInfo;
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "engine";
    app.apiVersion = VK_API_VERSION_1_2;
    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pNext = &features;
    info.pApplicationInfo = &app;
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = &layer;
    info.enabledExtensionCount = 1;
    info.ppEnabledExtensionNames = &extension;
    check(createInstance(&info, nullptr, &instance), "vkCreateInstance");
#define ENGINE_LOAD_INSTANCE(name) \
  name = reinterpret_cast<PFN_##name>(getInstanceProcAddr(instance, #name));
    ENGINE_INSTANCE_FUNCTIONS(ENGINE_LOAD_INSTANCE)
    check(vkCreateDebugUtilsMessengerEXT(instance, &messengerInfo, nullptr, &messenger),
          "vkCreateDebugUtilsMessengerEXT");
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(instance, &count, devices.data());
    for (VkPhysicalDevice candidate : devices) {
      VkPhysicalDeviceProperties properties{};
      vkGetPhysicalDeviceProperties(candidate, &properties);
      if (properties.deviceName != wantedDevice) continue;
      physical = candidate;
      deviceName = properties.deviceName;
      storageAlignment = properties.limits.minStorageBufferOffsetAlignment;
    }
    REQUIRE(physical);
    vkGetPhysicalDeviceMemoryProperties(physical, &memory);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
    const VkQueueFlags wanted = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    for (uint32_t f = 0; f < count && family == UINT32_MAX; ++f)
      if ((families[f].queueFlags & wanted) == wanted) family = f;
    REQUIRE(family != UINT32_MAX);
    device = createDevice({VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME});
#define ENGINE_LOAD_DEVICE(name) \
  name = reinterpret_cast<PFN_##name>(vkGetDeviceProcAddr(device, #name));
    ENGINE_DEVICE_FUNCTIONS(ENGINE_LOAD_DEVICE)
    vkGetDeviceQueue(device, family, 0, &queue);
  }

  VkDevice createDevice(const std::vector<const char*>& extensions) const {
    float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = family;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkDevice created = VK_NULL_HANDLE;
    check(vkCreateDevice(physical, &info, nullptr, &created), "vkCreateDevice");
    return created;
  }

  vk::ExternalDevice external() const { return {instance, physical, device, family, queue}; }

  ~Engine() {
    if (device) vkDestroyDevice(device, nullptr);
    if (messenger) vkDestroyDebugUtilsMessengerEXT(instance, messenger, nullptr);
    if (instance) vkDestroyInstance(instance, nullptr);
  }
};

// One host-visible buffer of the engine's: vertices, indices and the draw command at aligned
// offsets, as an engine might suballocate.
struct EngineBuffer {
  const Engine& engine;
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;
  RealtimeTargets targets;

  EngineBuffer(const Engine& e, VkDeviceSize vertexBytes, VkDeviceSize indexBytes) : engine(e) {
    auto align = [&](VkDeviceSize x) {
      return (x + engine.storageAlignment - 1) / engine.storageAlignment * engine.storageAlignment;
    };
    // Offsets not 0: the ranges must be honoured, not the whole buffer.
    const VkDeviceSize vertexOffset = align(4);
    const VkDeviceSize indexOffset = align(vertexOffset + vertexBytes);
    const VkDeviceSize drawOffset = align(indexOffset + indexBytes);
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = drawOffset + RealtimeRecorder::kDrawCommandBytes;
    info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT |
                 VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                 VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    check(engine.vkCreateBuffer(engine.device, &info, nullptr, &buffer), "vkCreateBuffer");
    VkMemoryRequirements requirements{};
    engine.vkGetBufferMemoryRequirements(engine.device, buffer, &requirements);
    const VkMemoryPropertyFlags wanted =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = requirements.size;
    alloc.memoryTypeIndex = UINT32_MAX;
    for (uint32_t t = 0; t < engine.memory.memoryTypeCount && alloc.memoryTypeIndex == UINT32_MAX;
         ++t)
      if ((requirements.memoryTypeBits & (1u << t)) &&
          (engine.memory.memoryTypes[t].propertyFlags & wanted) == wanted)
        alloc.memoryTypeIndex = t;
    REQUIRE(alloc.memoryTypeIndex != UINT32_MAX);
    check(engine.vkAllocateMemory(engine.device, &alloc, nullptr, &memory), "vkAllocateMemory");
    check(engine.vkBindBufferMemory(engine.device, buffer, memory, 0), "vkBindBufferMemory");
    check(engine.vkMapMemory(engine.device, memory, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
    targets.vertices = {buffer, vertexOffset, vertexBytes};
    targets.indices = {buffer, indexOffset, indexBytes};
    targets.drawCommand = {buffer, drawOffset, RealtimeRecorder::kDrawCommandBytes};
  }
  ~EngineBuffer() {
    engine.vkDestroyBuffer(engine.device, buffer, nullptr);
    engine.vkFreeMemory(engine.device, memory, nullptr);  // unmaps
  }
  template <typename T>
  const T* at(const DeviceBufferRange& range) const {
    return reinterpret_cast<const T*>(static_cast<const char*>(mapped) + range.offset);
  }
};

// The engine's own readback: everything written so far, visible to the host after its fence.
void toHostBarrier(const Engine& engine, VkCommandBuffer cmd) {
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  engine.vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                              0, 1, &barrier, 0, nullptr, 0, nullptr);
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
    vk::Context context(engine.external());
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
      recorder.record(commands[f], buffers.back()->targets);
      toHostBarrier(engine, commands[f]);
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
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.queueFamilyIndex = engine.family;
    VkCommandPool pool = VK_NULL_HANDLE;
    check(engine.vkCreateCommandPool(engine.device, &poolInfo, nullptr, &pool), "pool");
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocInfo.commandPool = pool;
    allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocInfo.commandBufferCount = 1;
    check(engine.vkAllocateCommandBuffers(engine.device, &allocInfo, &cmd), "command buffer");
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    check(engine.vkBeginCommandBuffer(cmd, &begin), "begin");
    engine.vkCmdFillBuffer(cmd, buffer.buffer, buffer.targets.indices.offset, 64, 0x7e55e7a);
    toHostBarrier(engine, cmd);
    check(engine.vkEndCommandBuffer(cmd), "end");
    VkFence fence = VK_NULL_HANDLE;
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    check(engine.vkCreateFence(engine.device, &fenceInfo, nullptr, &fence), "fence");
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    check(engine.vkQueueSubmit(engine.queue, 1, &submit, fence), "submit after the context");
    check(engine.vkWaitForFences(engine.device, 1, &fence, VK_TRUE, UINT64_MAX), "wait");
    CHECK(buffer.at<uint32_t>(buffer.targets.indices)[15] == 0x7e55e7au);
    engine.vkDestroyFence(engine.device, fence, nullptr);
    engine.vkDestroyCommandPool(engine.device, pool, nullptr);
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
