// The Vulkan context: instance (with validation when asked), the chosen physical device, a
// logical device with one queue, and one-time command submission. One context per thread:
// a Context is not thread-safe, two Contexts are independent.
#pragma once
#include "vk/backend_only.h"
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "vk/errors.h"

namespace tessera::vk {

// The dispatch tables (vk/loader.h, volk) are private to the Vulkan backend: only declared here,
// so that this header needs no VK_NO_PROTOTYPES. Code calling through vk() includes vk/loader.h.
struct InstanceTable;
struct DeviceTable;

enum class Validation {
  Off,          // no layers
  IfAvailable,  // enable VK_LAYER_KHRONOS_validation when installed
  Required,     // fail (VulkanUnavailable) when it is not installed; what the tests use
};

struct ContextOptions {
  Validation validation = Validation::Off;
  // Device choice: "" = automatic (discrete > integrated > virtual > CPU), else an index into
  // the list `tessera devices` prints, or a case-insensitive part of the device name.
  // When empty, the environment variable TESSERA_DEVICE is used if set.
  std::string device;
  // Called for every validation message at warning or error severity (tests fail on any).
  // Default: print to stderr.
  std::function<void(const std::string&)> onValidationMessage;
  // Extra extensions a window needs (the viewer: VK_KHR_surface and the platform's surface
  // extension on the instance, VK_KHR_swapchain on the device). Names must outlive the call.
  std::vector<const char*> instanceExtensions;
  std::vector<const char*> deviceExtensions;
};

// Where a context's fixed cost goes: wall-clock milliseconds, for `--stats` (the `setup` section)
// and bench/bench_startup.cpp. The driver compiles a pipeline's shader in
// vkCreateComputePipelines and may finish on its first use (lavapipe generates machine code at
// the first dispatch, from Mesa's shader disk cache when warm), hence firstSubmitMs.
struct ContextTimings {
  double instanceMs = 0;       // loading libvulkan, the drivers and layers; vkCreateInstance
  double deviceMs = 0;         // choosing the physical device; vkCreateDevice, pool and fence
  double pipelineCacheMs = 0;  // reading the pipeline cache file; vkCreatePipelineCache
  double pipelinesMs = 0;      // every ComputePipeline made so far (summed over threads)
  uint32_t pipelines = 0;
  double firstSubmitMs = 0;    // the first submitAndWait, recording to completion
  double submitsMs = 0;        // every submitAndWait, the first included
  uint32_t submits = 0;
  double contextMs() const { return instanceMs + deviceMs + pipelineCacheMs; }
};

struct DeviceInfo {
  uint32_t index = 0;  // position in vkEnumeratePhysicalDevices order
  std::string name;
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  uint32_t apiVersion = 0;
  VkDriverId driverId = static_cast<VkDriverId>(0);
  std::string driverName;
  std::string driverInfo;
  bool usable = false;         // meets Tessera's requirements
  std::string unusableReason;  // why not, when !usable
  uint64_t maxStorageBufferRange = 0;
  uint32_t maxTexelBufferElements = 0;  // texels one uniform texel buffer view may address
  // The largest single allocation (Vulkan 1.1's maintenance3 limit); 0 where not reported.
  uint64_t maxMemoryAllocationSize = 0;
  uint32_t maxComputeWorkGroupCountX = 0;
  float timestampPeriodNs = 0.0f;

  bool isLavapipe() const { return driverId == VK_DRIVER_ID_MESA_LLVMPIPE; }
  std::string typeName() const;
};

// An engine's own Vulkan objects, for a context that borrows them (docs/api.md, "Engine
// interop"). The device must be created from `physicalDevice` of `instance` with
// VK_KHR_push_descriptor enabled; `queue` is queue 0.. of `queueFamily`, which must support
// compute. Tessera never destroys them: they must outlive the context.
struct ExternalDevice {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  uint32_t queueFamily = 0;
  VkQueue queue = VK_NULL_HANDLE;
};

// Lists the physical devices (opens its own short-lived instance).
std::vector<DeviceInfo> listDevices();

class Context {
 public:
  explicit Context(const ContextOptions& options = {});
  // Borrows an engine's instance, device and queue: device functions through volk's device
  // table for that device (vk/loader.h), no instance or device of its own. Checks what
  // Tessera's pipelines need (Vulkan 1.1, push descriptors, a compute queue) and throws
  // VulkanUnavailable naming what is missing. Validation messages go to the engine's own
  // messenger (validationMessages() stays empty). The queue is used by submitAndWait (the
  // division counts): the caller must not use it from another thread meanwhile.
  explicit Context(const ExternalDevice& external);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  const DeviceTable& vk() const { return *deviceTable_; }
  VkInstance instance() const { return instance_; }
  VkDevice device() const { return device_; }
  VkPhysicalDevice physicalDevice() const { return physical_; }
  VkQueue queue() const { return queue_; }
  uint32_t queueFamily() const { return queueFamily_; }
  const DeviceInfo& info() const { return info_; }
  const VkPhysicalDeviceMemoryProperties& memoryProperties() const { return memory_; }
  bool validationEnabled() const { return validationEnabled_; }
  // False for a context borrowing an engine's device (ExternalDevice).
  bool ownsDevice() const { return ownsDevice_; }
  VkDeviceSize minStorageBufferOffsetAlignment() const { return minStorageOffsetAlignment_; }
  bool timestampsSupported() const { return timestampValidBits_ > 0; }
  uint32_t timestampValidBits() const { return timestampValidBits_; }
  bool queueSupportsGraphics() const { return queueGraphics_; }
  VkPipelineCache pipelineCache() const { return pipelineCache_; }
  // Where the pipeline cache is loaded from and saved to on destruction ("" = none), and how
  // many bytes were loaded (host/vk/pipeline_cache.h).
  const std::string& pipelineCachePath() const { return pipelineCachePath_; }
  size_t pipelineCacheLoadedBytes() const { return pipelineCacheLoadedBytes_; }
  // Optional features enabled when the device has them: tessellationShader and
  // pipelineStatisticsQuery (the tessellation-shader benchmark peer uses both).
  const VkPhysicalDeviceFeatures& enabledFeatures() const { return enabledFeatures_; }

  // Records commands into a fresh command buffer, submits, and waits for completion.
  void submitAndWait(const std::function<void(VkCommandBuffer)>& record);

  // The fixed costs so far (thread-safe).
  ContextTimings timings() const;
  // Called by ComputePipeline's constructor with the time it took.
  void notePipelineCreated(double ms);

  // Validation messages (warning or error severity) seen so far: the first
  // kKeptValidationMessages in full, then one line saying how many more came. The count is
  // of every message. Bounded because a long-lived context with validation on (an engine's
  // debug build) would otherwise keep every repeat of one message for hours.
  static constexpr size_t kKeptValidationMessages = 256;
  std::vector<std::string> validationMessages() const;
  size_t validationMessageCount() const;

  // Called by the debug messenger; public only for the C callback.
  void reportValidationMessage(const std::string& message);

 private:
  void createInstance(const ContextOptions& options);
  void choosePhysicalDevice(const std::string& selector);
  void createDevice(const std::vector<const char*>& extraDeviceExtensions);
  void adoptDevice(const ExternalDevice& external);
  void createCommandObjects();
  void createPipelineCache();
  void release();
  void savePipelineCache();

  // Per context, so two contexts live side by side (vk/loader.h).
  std::unique_ptr<InstanceTable> instanceTable_;
  std::unique_ptr<DeviceTable> deviceTable_;
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  bool queueGraphics_ = false;
  uint32_t timestampValidBits_ = 0;
  DeviceInfo info_;
  VkPhysicalDeviceMemoryProperties memory_{};
  VkCommandPool commandPool_ = VK_NULL_HANDLE;
  VkCommandBuffer commandBuffer_ = VK_NULL_HANDLE;  // commandPool_'s one (recordAndSubmit)
  VkFence fence_ = VK_NULL_HANDLE;
  VkPipelineCache pipelineCache_ = VK_NULL_HANDLE;
  std::string pipelineCachePath_;
  size_t pipelineCacheLoadedBytes_ = 0;
  VkPhysicalDeviceFeatures enabledFeatures_{};
  bool validationEnabled_ = false;
  bool ownsDevice_ = true;
  VkDeviceSize minStorageOffsetAlignment_ = 1;
  std::function<void(const std::string&)> onValidationMessage_;
  mutable std::mutex timingsMutex_;
  ContextTimings timings_;
  mutable std::mutex messagesMutex_;
  std::vector<std::string> messages_;  // the first kKeptValidationMessages
  size_t messageCount_ = 0;            // all of them
};

}  // namespace tessera::vk
