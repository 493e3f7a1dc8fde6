#include "vk/context.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "common/stopwatch.h"
#include "vk/device_select.h"
#include "vk/loader.h"
#include "vk/one_time_commands.h"
#include "vk/pipeline_cache.h"

namespace tessera::vk {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

// Global functions: volk's, set by ensureLoaded().
bool hasInstanceLayer(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  return std::any_of(layers.begin(), layers.end(),
                     [&](const auto& l) { return std::strcmp(l.layerName, name) == 0; });
}

bool hasInstanceExtension(const char* layer, const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceExtensionProperties(layer, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateInstanceExtensionProperties(layer, &count, extensions.data());
  return std::any_of(extensions.begin(), extensions.end(),
                     [&](const auto& e) { return std::strcmp(e.extensionName, name) == 0; });
}

VKAPI_ATTR VkBool32 VKAPI_CALL debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                             VkDebugUtilsMessageTypeFlagsEXT,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data,
                                             void* user) {
  const char* level =
      (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error" : "warning";
  std::string message = std::string("Vulkan validation ") + level + ": " +
                        (data && data->pMessage ? data->pMessage : "(no text)");
  static_cast<Context*>(user)->reportValidationMessage(message);
  return VK_FALSE;
}

}  // namespace

Context::Context(const ContextOptions& options) {
  onValidationMessage_ = options.onValidationMessage;
  try {
    Stopwatch step;
    createInstance(options);
    timings_.instanceMs = step.elapsedMs();
    step.restart();
    std::string selector = options.device;
    if (selector.empty()) {
      const char* env = std::getenv("TESSERA_DEVICE");
      if (env) selector = env;
    }
    choosePhysicalDevice(selector);
    createDevice(options.deviceExtensions);
    timings_.deviceMs = step.elapsedMs();
    step.restart();
    createPipelineCache();
    timings_.pipelineCacheMs = step.elapsedMs();
  } catch (...) {
    release();  // what was made before the failure
    throw;
  }
}

Context::Context(const ExternalDevice& external) : ownsDevice_(false) {
  try {
    Stopwatch step;
    adoptDevice(external);
    timings_.deviceMs = step.elapsedMs();
    step.restart();
    createPipelineCache();
    timings_.pipelineCacheMs = step.elapsedMs();
  } catch (...) {
    release();
    throw;
  }
}

Context::~Context() { release(); }

void Context::release() {
  // Without its table (loading failed) a handle cannot be destroyed; that only happens when
  // Vulkan itself is broken.
  if (device_ && deviceTable_) {
    // A borrowed device: our own submits were waited on; the engine waits for the frames it
    // submitted (docs/realtime.md) and may be using its queues from other threads.
    if (ownsDevice_) deviceTable_->vkDeviceWaitIdle(device_);
    if (pipelineCache_) {
      savePipelineCache();
      deviceTable_->vkDestroyPipelineCache(device_, pipelineCache_, nullptr);
    }
    if (fence_) deviceTable_->vkDestroyFence(device_, fence_, nullptr);
    if (commandPool_) deviceTable_->vkDestroyCommandPool(device_, commandPool_, nullptr);
    if (ownsDevice_) deviceTable_->vkDestroyDevice(device_, nullptr);
    device_ = VK_NULL_HANDLE;
  }
  if (!ownsDevice_) {  // the engine's instance: leave it alone
    instance_ = VK_NULL_HANDLE;
    return;
  }
  if (messenger_ && instanceTable_) {
    instanceTable_->vkDestroyDebugUtilsMessengerEXT(instance_, messenger_, nullptr);
    messenger_ = VK_NULL_HANDLE;
  }
  if (instance_ && instanceTable_) {
    instanceTable_->vkDestroyInstance(instance_, nullptr);
    instance_ = VK_NULL_HANDLE;
  }
}

void Context::createInstance(const ContextOptions& options) {
  ensureLoaded();
  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  if (options.validation != Validation::Off) {
    if (hasInstanceLayer(kValidationLayer)) {
      layers.push_back(kValidationLayer);
      validationEnabled_ = true;
    } else if (options.validation == Validation::Required) {
      throw VulkanUnavailable(std::string(kValidationLayer) +
                              " is required but not installed: `apt-get install "
                              "vulkan-validationlayers`");
    }
  }
  bool debugUtils = validationEnabled_ &&
                    (hasInstanceExtension(nullptr, VK_EXT_DEBUG_UTILS_EXTENSION_NAME) ||
                     hasInstanceExtension(kValidationLayer, VK_EXT_DEBUG_UTILS_EXTENSION_NAME));
  if (debugUtils) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  extensions.insert(extensions.end(), options.instanceExtensions.begin(),
                    options.instanceExtensions.end());

  // Messages during vkCreateInstance itself reach this messenger through pNext.
  VkDebugUtilsMessengerCreateInfoEXT messengerInfo{
      VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messengerInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                  VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messengerInfo.pfnUserCallback = debugCallback;
  messengerInfo.pUserData = this;
  // Synchronization validation catches missing barriers between dispatches.
  VkValidationFeatureEnableEXT enables[] = {
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enables;
  features.pNext = debugUtils ? &messengerInfo : nullptr;

  instance_ = vk::createInstance(
      layers, extensions, validationEnabled_ ? static_cast<const void*>(&features) : nullptr);
  instanceTable_ = std::make_unique<InstanceTable>(loadInstanceTable(instance_));
  if (debugUtils && instanceTable_->vkCreateDebugUtilsMessengerEXT)
    VK_CHECK(instanceTable_->vkCreateDebugUtilsMessengerEXT(instance_, &messengerInfo, nullptr,
                                                            &messenger_));
}

void Context::choosePhysicalDevice(const std::string& selector) {
  uint32_t count = 0;
  VK_CHECK(instanceTable_->vkEnumeratePhysicalDevices(instance_, &count, nullptr));
  std::vector<VkPhysicalDevice> physical(count);
  VK_CHECK(instanceTable_->vkEnumeratePhysicalDevices(instance_, &count, physical.data()));
  std::vector<DeviceInfo> devices;
  for (uint32_t i = 0; i < count; ++i)
    devices.push_back(describeDevice(*instanceTable_, physical[i], i));
  size_t chosen = selectDevice(devices, selector);
  physical_ = physical[chosen];
  info_ = devices[chosen];
  instanceTable_->vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
}

void Context::createDevice(const std::vector<const char*>& extraDeviceExtensions) {
  uint32_t familyCount = 0;
  instanceTable_->vkGetPhysicalDeviceQueueFamilyProperties(physical_, &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  instanceTable_->vkGetPhysicalDeviceQueueFamilyProperties(physical_, &familyCount,
                                                           families.data());
  // One queue for everything: prefer a family that also draws (tessera render).
  int chosen = -1;
  for (uint32_t i = 0; i < familyCount; ++i) {
    VkQueueFlags flags = families[i].queueFlags;
    if (!(flags & VK_QUEUE_COMPUTE_BIT)) continue;
    if (chosen < 0 || ((flags & VK_QUEUE_GRAPHICS_BIT) &&
                       !(families[chosen].queueFlags & VK_QUEUE_GRAPHICS_BIT)))
      chosen = static_cast<int>(i);
  }
  if (chosen < 0) throw VulkanUnavailable("device '" + info_.name + "' has no compute queue");
  queueFamily_ = static_cast<uint32_t>(chosen);
  queueGraphics_ = families[chosen].queueFlags & VK_QUEUE_GRAPHICS_BIT;
  timestampValidBits_ = families[chosen].timestampValidBits;

  float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = queueFamily_;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;
  std::vector<const char*> extensions = requiredDeviceExtensions();
  extensions.insert(extensions.end(), extraDeviceExtensions.begin(), extraDeviceExtensions.end());
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VkPhysicalDeviceFeatures available{};
  instanceTable_->vkGetPhysicalDeviceFeatures(physical_, &available);
  enabledFeatures_.tessellationShader = available.tessellationShader;
  enabledFeatures_.pipelineStatisticsQuery = available.pipelineStatisticsQuery;
  // The peer's capture pipeline (TessShaderPeer::captureFrame: its screen error in the bench)
  // records triangles from a geometry shader into a storage buffer.
  enabledFeatures_.geometryShader = available.geometryShader;
  enabledFeatures_.vertexPipelineStoresAndAtomics = available.vertexPipelineStoresAndAtomics;
  info.pEnabledFeatures = &enabledFeatures_;
  VK_CHECK(instanceTable_->vkCreateDevice(physical_, &info, nullptr, &device_));
  deviceTable_ = std::make_unique<DeviceTable>(loadDeviceTable(instance_, device_));
  if (!deviceTable_->vkCmdPushDescriptorSetKHR)
    throw VulkanUnavailable("device '" + info_.name + "' lacks vkCmdPushDescriptorSetKHR");
  deviceTable_->vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
  createCommandObjects();
}

void Context::adoptDevice(const ExternalDevice& external) {
  if (!external.instance || !external.physicalDevice || !external.device || !external.queue)
    throw VulkanUnavailable(
        "engine interop: the instance, physical device, device and queue must all be given");
  ensureLoaded();
  instance_ = external.instance;
  physical_ = external.physicalDevice;
  instanceTable_ = std::make_unique<InstanceTable>(loadInstanceTable(instance_));
  info_ = describeDevice(*instanceTable_, physical_, 0);
  if (!info_.usable)
    throw VulkanUnavailable("engine interop: device '" + info_.name +
                            "' is unusable: " + info_.unusableReason);
  instanceTable_->vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
  uint32_t familyCount = 0;
  instanceTable_->vkGetPhysicalDeviceQueueFamilyProperties(physical_, &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  instanceTable_->vkGetPhysicalDeviceQueueFamilyProperties(physical_, &familyCount,
                                                           families.data());
  if (external.queueFamily >= familyCount)
    throw VulkanUnavailable("engine interop: queue family " +
                            std::to_string(external.queueFamily) + " does not exist on '" +
                            info_.name + "' (" + std::to_string(familyCount) + " families)");
  const VkQueueFamilyProperties& family = families[external.queueFamily];
  if (!(family.queueFlags & VK_QUEUE_COMPUTE_BIT))
    throw VulkanUnavailable("engine interop: queue family " +
                            std::to_string(external.queueFamily) +
                            " has no compute (VK_QUEUE_COMPUTE_BIT), which every Tessera "
                            "pipeline needs");
  queueFamily_ = external.queueFamily;
  queue_ = external.queue;
  queueGraphics_ = family.queueFlags & VK_QUEUE_GRAPHICS_BIT;
  timestampValidBits_ = family.timestampValidBits;
  // The engine chose the features; Tessera's compute pipelines need none beyond Vulkan 1.0's,
  // only the optional benchmark peer reads these (left off: we cannot see what was enabled).
  enabledFeatures_ = VkPhysicalDeviceFeatures{};
  device_ = external.device;
  deviceTable_ = std::make_unique<DeviceTable>(loadDeviceTable(instance_, device_));
  // vkGetDeviceProcAddr returns null for an extension the device was created without.
  if (!deviceTable_->vkCmdPushDescriptorSetKHR)
    throw VulkanUnavailable("engine interop: device '" + info_.name + "' was created without " +
                            VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME +
                            " (add it to VkDeviceCreateInfo::ppEnabledExtensionNames)");
  createCommandObjects();
}

void Context::createCommandObjects() {
  VkPhysicalDeviceProperties properties{};
  instanceTable_->vkGetPhysicalDeviceProperties(physical_, &properties);
  minStorageOffsetAlignment_ = properties.limits.minStorageBufferOffsetAlignment;
  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  poolInfo.queueFamilyIndex = queueFamily_;
  VK_CHECK(deviceTable_->vkCreateCommandPool(device_, &poolInfo, nullptr, &commandPool_));
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VK_CHECK(deviceTable_->vkCreateFence(device_, &fenceInfo, nullptr, &fence_));
}

void Context::createPipelineCache() {
  VkPhysicalDeviceProperties properties{};
  instanceTable_->vkGetPhysicalDeviceProperties(physical_, &properties);
  pipelineCachePath_ = vk::pipelineCachePath(properties);
  std::vector<char> cached = readPipelineCache(pipelineCachePath_);
  pipelineCacheLoadedBytes_ = cached.size();
  VkPipelineCacheCreateInfo cacheInfo{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
  cacheInfo.initialDataSize = cached.size();
  cacheInfo.pInitialData = cached.empty() ? nullptr : cached.data();
  VK_CHECK(deviceTable_->vkCreatePipelineCache(device_, &cacheInfo, nullptr, &pipelineCache_));
}

void Context::savePipelineCache() {
  if (pipelineCachePath_.empty() || !deviceTable_->vkGetPipelineCacheData) return;
  size_t bytes = 0;
  if (deviceTable_->vkGetPipelineCacheData(device_, pipelineCache_, &bytes, nullptr) !=
          VK_SUCCESS ||
      bytes == 0)
    return;
  std::vector<char> data(bytes);
  if (deviceTable_->vkGetPipelineCacheData(device_, pipelineCache_, &bytes, data.data()) !=
      VK_SUCCESS)
    return;
  data.resize(bytes);
  // Only when it grew: a run that compiled nothing new leaves the file alone.
  if (bytes > pipelineCacheLoadedBytes_) writePipelineCache(pipelineCachePath_, data);
}

void Context::submitAndWait(const std::function<void(VkCommandBuffer)>& record) {
  const Stopwatch stopwatch;
  recordAndSubmit(*deviceTable_, device_, queue_, commandPool_, commandBuffer_, fence_, record);
  VK_CHECK(deviceTable_->vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX));
  const double ms = stopwatch.elapsedMs();
  std::lock_guard<std::mutex> lock(timingsMutex_);
  if (timings_.submits++ == 0) timings_.firstSubmitMs = ms;
  timings_.submitsMs += ms;
}

ContextTimings Context::timings() const {
  std::lock_guard<std::mutex> lock(timingsMutex_);
  return timings_;
}

void Context::notePipelineCreated(double ms) {
  std::lock_guard<std::mutex> lock(timingsMutex_);
  ++timings_.pipelines;
  timings_.pipelinesMs += ms;
}

void Context::reportValidationMessage(const std::string& message) {
  {
    std::lock_guard<std::mutex> lock(messagesMutex_);
    if (messageCount_++ < kKeptValidationMessages) messages_.push_back(message);
  }
  if (onValidationMessage_)
    onValidationMessage_(message);
  else
    std::fprintf(stderr, "%s\n", message.c_str());
}

std::vector<std::string> Context::validationMessages() const {
  std::lock_guard<std::mutex> lock(messagesMutex_);
  std::vector<std::string> messages = messages_;
  if (messageCount_ > messages_.size())
    messages.push_back("(" + std::to_string(messageCount_ - messages_.size()) +
                       " more validation messages, not kept)");
  return messages;
}

size_t Context::validationMessageCount() const {
  std::lock_guard<std::mutex> lock(messagesMutex_);
  return messageCount_;
}

}  // namespace tessera::vk
