// An engine with its own Vulkan that embeds Tessera (tessera/vulkan.h, docs/api.md "Engines
// with their own Vulkan device"), headless: it makes its instance and device, lends them to
// Tessera, meshes the teapot on them, records a real-time frame of it into its own command
// buffer and buffer, submits with its own fence and reads the draw command back.
//   engine <teapot.bpt>
// Built two ways (tests/engine/CMakeLists.txt): ENGINE_USES_VOLK 0 calls the Vulkan loader's
// prototypes (libvulkan.so), 1 compiles its own volk.c, as many engines do. Against an
// installed Tessera: examples/engine/CMakeLists.txt (scripts/check-install.sh builds it).
// Exit 0 only if every check passed: validation messages on the engine's instance (where the
// layer is installed), Tessera's mesh on the lent device against its CPU path (bit for bit on
// lavapipe, else within 1% of the triangles), the recorded draw against prepare()'s count, and
// the engine's own Vulkan after Tessera's objects are gone.
#if ENGINE_USES_VOLK
#include <volk.h>
#else
#include <vulkan/vulkan.h>
#endif
#include <tessera/vulkan.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

int validationMessages = 0;

VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                         VkDebugUtilsMessageTypeFlagsEXT,
                                         const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
  ++validationMessages;
  std::fprintf(stderr, "engine: validation: %s\n", data->pMessage);
  return VK_FALSE;
}

bool hasLayer(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  for (const VkLayerProperties& layer : layers)
    if (std::strcmp(layer.layerName, name) == 0) return true;
  return false;
}

struct Failure {
  std::string what;
};

void check(bool ok, const std::string& what) {
  if (!ok) throw Failure{what};
}

void check(VkResult result, const std::string& what) {
  check(result == VK_SUCCESS, what + ": VkResult " + std::to_string(int(result)));
}

// The engine's Vulkan: instance (validation where installed), the first device with a queue
// family that computes and draws, the device with VK_KHR_push_descriptor (Tessera needs it).
struct EngineVulkan {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  std::string deviceName;
  uint32_t family = 0;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  bool validation = false;

  EngineVulkan() {
    const char* layer = "VK_LAYER_KHRONOS_validation";
    validation = hasLayer(layer);
    VkDebugUtilsMessengerCreateInfoEXT messenger{};
    messenger.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
    messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger.pfnUserCallback = onMessage;
    VkApplicationInfo app{};
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = "engine";
    app.apiVersion = VK_API_VERSION_1_1;
    const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    VkInstanceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    info.pNext = validation ? &messenger : nullptr;  // the instance's life is checked too
    info.pApplicationInfo = &app;
    info.enabledLayerCount = validation ? 1 : 0;
    info.ppEnabledLayerNames = &layer;
    info.enabledExtensionCount = validation ? 1 : 0;
    info.ppEnabledExtensionNames = &extension;
    check(vkCreateInstance(&info, nullptr, &instance), "vkCreateInstance");
#if ENGINE_USES_VOLK
    volkLoadInstance(instance);
#endif
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(instance, &count, devices.data());
    const VkQueueFlags wanted = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    for (VkPhysicalDevice candidate : devices) {
      vkGetPhysicalDeviceQueueFamilyProperties(candidate, &count, nullptr);
      std::vector<VkQueueFamilyProperties> families(count);
      vkGetPhysicalDeviceQueueFamilyProperties(candidate, &count, families.data());
      for (uint32_t f = 0; f < count && !physical; ++f)
        if ((families[f].queueFlags & wanted) == wanted) {
          physical = candidate;
          family = f;
        }
      if (physical) break;
    }
    check(physical != VK_NULL_HANDLE, "no Vulkan device with a graphics and compute queue");
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(physical, &properties);
    deviceName = properties.deviceName;
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{};
    queueInfo.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    queueInfo.queueFamilyIndex = family;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    const char* pushDescriptor = VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME;
    VkDeviceCreateInfo deviceInfo{};
    deviceInfo.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    deviceInfo.enabledExtensionCount = 1;
    deviceInfo.ppEnabledExtensionNames = &pushDescriptor;
    check(vkCreateDevice(physical, &deviceInfo, nullptr, &device), "vkCreateDevice");
#if ENGINE_USES_VOLK
    volkLoadDevice(device);
#endif
    vkGetDeviceQueue(device, family, 0, &queue);
  }
  ~EngineVulkan() {
    if (device) vkDestroyDevice(device, nullptr);
    if (instance) vkDestroyInstance(instance, nullptr);
  }
  tessera::VulkanDevice lent() const { return {instance, physical, device, family, queue}; }
};

// One host-visible buffer holding a frame: vertices, indices and the draw command.
struct FrameBuffer {
  const EngineVulkan& vk;
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;
  tessera::RealtimeFrameTargets targets;

  FrameBuffer(const EngineVulkan& engine, const tessera::RealtimeFrameInfo& frame) : vk(engine) {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(vk.physical, &properties);
    const VkDeviceSize align = properties.limits.minStorageBufferOffsetAlignment;
    const VkDeviceSize indexOffset = (frame.vertexBytes + align - 1) / align * align;
    const VkDeviceSize drawOffset = (indexOffset + frame.indexBytes + 3) / 4 * 4;
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = drawOffset + tessera::RealtimeScene::kDrawCommandBytes;
    info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT |
                 VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                 VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    check(vkCreateBuffer(vk.device, &info, nullptr, &buffer), "vkCreateBuffer");
    VkMemoryRequirements needs;
    vkGetBufferMemoryRequirements(vk.device, buffer, &needs);
    VkPhysicalDeviceMemoryProperties types;
    vkGetPhysicalDeviceMemoryProperties(vk.physical, &types);
    const VkMemoryPropertyFlags host =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    VkMemoryAllocateInfo alloc{};
    alloc.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    alloc.allocationSize = needs.size;
    alloc.memoryTypeIndex = UINT32_MAX;
    for (uint32_t t = 0; t < types.memoryTypeCount && alloc.memoryTypeIndex == UINT32_MAX; ++t)
      if ((needs.memoryTypeBits & (1u << t)) && (types.memoryTypes[t].propertyFlags & host) == host)
        alloc.memoryTypeIndex = t;
    check(alloc.memoryTypeIndex != UINT32_MAX, "no host-visible memory for the frame");
    check(vkAllocateMemory(vk.device, &alloc, nullptr, &memory), "vkAllocateMemory");
    check(vkBindBufferMemory(vk.device, buffer, memory, 0), "vkBindBufferMemory");
    check(vkMapMemory(vk.device, memory, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
    targets.vertices = {buffer, 0, frame.vertexBytes};
    targets.indices = {buffer, indexOffset, frame.indexBytes};
    targets.drawCommand = {buffer, drawOffset, tessera::RealtimeScene::kDrawCommandBytes};
  }
  ~FrameBuffer() {
    vkDestroyBuffer(vk.device, buffer, nullptr);
    vkFreeMemory(vk.device, memory, nullptr);
  }
  const VkDrawIndexedIndirectCommand& draw() const {
    return *reinterpret_cast<const VkDrawIndexedIndirectCommand*>(static_cast<const char*>(mapped) +
                                                                  targets.drawCommand.offset);
  }
};

// Records scene.record into a command buffer of the engine's, with a barrier making the writes
// visible to the host (a renderer would draw instead), submits it and waits on its fence.
void recordAndSubmit(const EngineVulkan& vk, tessera::RealtimeScene& scene,
                     const FrameBuffer& frame) {
  VkCommandPoolCreateInfo poolInfo{};
  poolInfo.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
  poolInfo.queueFamilyIndex = vk.family;
  VkCommandPool pool = VK_NULL_HANDLE;
  check(vkCreateCommandPool(vk.device, &poolInfo, nullptr, &pool), "vkCreateCommandPool");
  VkCommandBufferAllocateInfo allocInfo{};
  allocInfo.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
  allocInfo.commandPool = pool;
  allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocInfo.commandBufferCount = 1;
  VkCommandBuffer commands = VK_NULL_HANDLE;
  check(vkAllocateCommandBuffers(vk.device, &allocInfo, &commands), "vkAllocateCommandBuffers");
  VkCommandBufferBeginInfo begin{};
  begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(commands, &begin), "vkBeginCommandBuffer");
  scene.record(commands, frame.targets);
  VkMemoryBarrier toHost{};
  toHost.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  toHost.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0,
                       1, &toHost, 0, nullptr, 0, nullptr);
  check(vkEndCommandBuffer(commands), "vkEndCommandBuffer");
  VkFenceCreateInfo fenceInfo{};
  fenceInfo.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
  VkFence fence = VK_NULL_HANDLE;
  check(vkCreateFence(vk.device, &fenceInfo, nullptr, &fence), "vkCreateFence");
  VkSubmitInfo submit{};
  submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commands;
  check(vkQueueSubmit(vk.queue, 1, &submit, fence), "vkQueueSubmit");
  check(vkWaitForFences(vk.device, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
  vkDestroyFence(vk.device, fence, nullptr);
  vkDestroyCommandPool(vk.device, pool, nullptr);
}

void run(const char* teapotPath) {
#if ENGINE_USES_VOLK
  check(volkInitialize(), "volkInitialize (no Vulkan loader)");
#endif
  uint32_t version = 0;
  check(vkEnumerateInstanceVersion(&version), "vkEnumerateInstanceVersion");
  check(version >= VK_API_VERSION_1_1, "a Vulkan 1.1 loader");
  EngineVulkan vk;
  const std::vector<tessera::Patch> teapot = tessera::loadPatches(teapotPath);
  {
    // Tessera's meshes on the lent device, against its CPU path.
    tessera::Tessellator onEngine = tessera::tessellatorOnDevice(vk.lent());
    check(onEngine.usesVulkan() && onEngine.deviceName() == vk.deviceName,
          "Tessera runs on the lent device");
    const tessera::Mesh gpu = onEngine.tessellateToTolerance(teapot, 0.01);
    const tessera::Mesh cpu =
        tessera::Tessellator({tessera::Device::Cpu}).tessellateToTolerance(teapot, 0.01);
    if (vk.deviceName.find("llvmpipe") != std::string::npos)
      check(gpu.positions == cpu.positions && gpu.indices == cpu.indices,
            "lavapipe's mesh is the CPU path's, bit for bit");
    else
      check(std::abs(double(gpu.triangleCount()) - double(cpu.triangleCount())) <=
                0.01 * double(cpu.triangleCount()),
            "the device's triangle count within 1% of the CPU's");

    // A real-time frame, recorded into the engine's command buffer and buffer.
    tessera::RealtimeScene scene(vk.lent(), teapot);
    const tessera::View view =
        tessera::lookAtView({4, -8, 5}, {0, 0, 1.5}, {0, 0, 1}, 45, 1280, 720, 0.1, 100);
    const tessera::RealtimeFrameInfo info = scene.prepare(view);
    check(info.triangles > 0, "the frame has triangles");
    FrameBuffer frame(vk, info);
    recordAndSubmit(vk, scene, frame);
    check(frame.draw().indexCount == 3 * info.triangles && frame.draw().instanceCount == 1,
          "the recorded draw command holds the frame's indices");
    std::printf(
        "engine: %s, validation %s, on %s: tessellateToTolerance 0.01 gave %zu "
        "triangles (cpu %zu); a 1 px frame drew %zu triangles of %zu visible patches\n",
        ENGINE_USES_VOLK ? "its own volk" : "the Vulkan loader",
        vk.validation ? "on" : "not installed", vk.deviceName.c_str(), gpu.triangleCount(),
        cpu.triangleCount(), size_t(frame.draw().indexCount / 3), info.visiblePatches);
  }  // Tessera's objects go; the engine's device stays and must still work
  check(vkDeviceWaitIdle(vk.device), "the engine's device after Tessera");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <teapot.bpt>\n", argv[0]);
    return 2;
  }
  try {
    run(argv[1]);
  } catch (const Failure& f) {
    std::fprintf(stderr, "engine: FAILED: %s\n", f.what.c_str());
    return 1;
  } catch (const tessera::Error& e) {
    std::fprintf(stderr, "engine: tessera: %s\n", e.what());
    return 1;
  }
  if (validationMessages != 0) {
    std::fprintf(stderr, "engine: FAILED: %d validation messages\n", validationMessages);
    return 1;
  }
  std::printf("engine: OK\n");
  return 0;
}
