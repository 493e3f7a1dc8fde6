// An engine's own Vulkan, as the interop tests need it (test_realtime_interop.cpp,
// test_public_vulkan.cpp): its own loader handle and instance (validation with synchronisation
// checks, its own messenger collecting every warning and error), the physical device Tessera's
// test context chose, a graphics + compute queue, its device (push descriptors on), and
// host-visible buffers at non-zero offsets. Include after <vulkan/vulkan.h> with
// VK_NO_PROTOTYPES: the engine loads its functions itself, as volk users do.
#pragma once
#include <dlfcn.h>

#include <catch2/catch.hpp>

#include <functional>
#include <string>
#include <vector>

namespace tessera::test {

#define ENGINE_INSTANCE_FUNCTIONS(X)                                                  \
  X(vkDestroyInstance)                                                                \
  X(vkEnumeratePhysicalDevices)                                                       \
  X(vkGetPhysicalDeviceProperties) X(vkGetPhysicalDeviceQueueFamilyProperties)        \
      X(vkGetPhysicalDeviceMemoryProperties) X(vkCreateDevice) X(vkGetDeviceProcAddr) \
          X(vkCreateDebugUtilsMessengerEXT) X(vkDestroyDebugUtilsMessengerEXT)
#define ENGINE_DEVICE_FUNCTIONS(X)                                                               \
  X(vkDestroyDevice)                                                                             \
  X(vkGetDeviceQueue)                                                                            \
  X(vkDeviceWaitIdle) X(vkCreateCommandPool) X(vkDestroyCommandPool) X(vkAllocateCommandBuffers) \
      X(vkBeginCommandBuffer) X(vkEndCommandBuffer) X(vkQueueSubmit) X(vkCreateFence)            \
          X(vkDestroyFence) X(vkWaitForFences) X(vkResetFences) X(vkCreateBuffer)                \
              X(vkDestroyBuffer) X(vkGetBufferMemoryRequirements) X(vkAllocateMemory)            \
                  X(vkFreeMemory) X(vkBindBufferMemory) X(vkMapMemory) X(vkCmdPipelineBarrier)   \
                      X(vkCmdFillBuffer) X(vkResetCommandPool)
#define ENGINE_MEMBER(name) PFN_##name name = nullptr;

inline VKAPI_ATTR VkBool32 VKAPI_CALL
collectMessage(VkDebugUtilsMessageSeverityFlagBitsEXT, VkDebugUtilsMessageTypeFlagsEXT,
               const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  static_cast<std::vector<std::string>*>(user)->push_back(data && data->pMessage ? data->pMessage
                                                                                 : "(no text)");
  return VK_FALSE;
}

inline void check(VkResult result, const char* what) {
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

  ~Engine() {
    if (device) vkDestroyDevice(device, nullptr);
    if (messenger) vkDestroyDebugUtilsMessengerEXT(instance, messenger, nullptr);
    if (instance) vkDestroyInstance(instance, nullptr);
  }
};

// A range of one of the engine's buffers, and the three a frame is recorded into.
struct EngineRange {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceSize offset = 0, size = 0;
};
struct EngineTargets {
  EngineRange vertices, indices, drawCommand;
};

// One host-visible buffer of the engine's: vertices, indices and the draw command at aligned
// offsets, as an engine might suballocate.
struct EngineBuffer {
  const Engine& engine;
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;
  EngineTargets targets;

  EngineBuffer(const Engine& e, VkDeviceSize vertexBytes, VkDeviceSize indexBytes) : engine(e) {
    auto align = [&](VkDeviceSize x) {
      return (x + engine.storageAlignment - 1) / engine.storageAlignment * engine.storageAlignment;
    };
    // Offsets not 0: the ranges must be honoured, not the whole buffer.
    const VkDeviceSize vertexOffset = align(4);
    const VkDeviceSize indexOffset = align(vertexOffset + vertexBytes);
    const VkDeviceSize drawOffset = align(indexOffset + indexBytes);
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = drawOffset + sizeof(VkDrawIndexedIndirectCommand);
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
    targets.drawCommand = {buffer, drawOffset, sizeof(VkDrawIndexedIndirectCommand)};
  }
  ~EngineBuffer() {
    engine.vkDestroyBuffer(engine.device, buffer, nullptr);
    engine.vkFreeMemory(engine.device, memory, nullptr);  // unmaps
  }
  template <typename T>
  const T* at(const EngineRange& range) const {
    return reinterpret_cast<const T*>(static_cast<const char*>(mapped) + range.offset);
  }
};

// The engine's own readback: everything written so far, visible to the host after its fence.
inline void toHostBarrier(const Engine& engine, VkCommandBuffer cmd) {
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  engine.vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                              0, 1, &barrier, 0, nullptr, 0, nullptr);
}

// A command buffer of the engine's own pool: record with `work` (then a barrier to the host),
// submit with a fence of its own, wait.
inline void submitOnce(const Engine& engine, const std::function<void(VkCommandBuffer)>& work) {
  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.queueFamilyIndex = engine.family;
  VkCommandPool pool = VK_NULL_HANDLE;
  check(engine.vkCreateCommandPool(engine.device, &poolInfo, nullptr, &pool), "pool");
  VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocInfo.commandPool = pool;
  allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocInfo.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  check(engine.vkAllocateCommandBuffers(engine.device, &allocInfo, &cmd), "command buffer");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(engine.vkBeginCommandBuffer(cmd, &begin), "begin");
  work(cmd);
  toHostBarrier(engine, cmd);
  check(engine.vkEndCommandBuffer(cmd), "end");
  VkFence fence = VK_NULL_HANDLE;
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  check(engine.vkCreateFence(engine.device, &fenceInfo, nullptr, &fence), "fence");
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  check(engine.vkQueueSubmit(engine.queue, 1, &submit, fence), "submit");
  check(engine.vkWaitForFences(engine.device, 1, &fence, VK_TRUE, UINT64_MAX), "wait");
  engine.vkDestroyFence(engine.device, fence, nullptr);
  engine.vkDestroyCommandPool(engine.device, pool, nullptr);
}

}  // namespace tessera::test
