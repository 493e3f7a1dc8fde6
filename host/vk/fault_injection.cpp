#include "vk/fault_injection.h"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace tessera::vk {
namespace {

struct FaultSpec {
  std::string kind;
  long nth = 1;
};

const FaultSpec& faultSpec() {
  static const FaultSpec spec = [] {
    FaultSpec s;
    const char* env = std::getenv("TESSERA_VK_FAULT");
    if (!env) return s;
    std::string text = env;
    size_t colon = text.find(':');
    s.kind = text.substr(0, colon);
    if (colon != std::string::npos) s.nth = std::max(1L, std::strtol(text.c_str() + colon + 1, nullptr, 10));
    return s;
  }();
  return spec;
}

// Wrappers are plain functions, so their state is process-wide: faults are for tests, one
// process per test.
std::atomic<long> allocCountdown{0};
PFN_vkAllocateMemory realAllocateMemory = nullptr;
VKAPI_ATTR VkResult VKAPI_CALL failingAllocateMemory(VkDevice device, const VkMemoryAllocateInfo* info,
                                                     const VkAllocationCallbacks* callbacks,
                                                     VkDeviceMemory* memory) {
  if (--allocCountdown == 0) return VK_ERROR_OUT_OF_DEVICE_MEMORY;
  return realAllocateMemory(device, info, callbacks, memory);
}

std::atomic<long> submitCountdown{0};
PFN_vkQueueSubmit realQueueSubmit = nullptr;
VKAPI_ATTR VkResult VKAPI_CALL losingQueueSubmit(VkQueue queue, uint32_t count,
                                                 const VkSubmitInfo* submits, VkFence fence) {
  if (--submitCountdown <= 0) return VK_ERROR_DEVICE_LOST;  // lost stays lost
  return realQueueSubmit(queue, count, submits, fence);
}

VKAPI_ATTR VkResult VKAPI_CALL noPhysicalDevices(VkInstance, uint32_t* count, VkPhysicalDevice*) {
  *count = 0;
  return VK_SUCCESS;
}

PFN_vkEnumerateDeviceExtensionProperties realEnumerateDeviceExtensions = nullptr;
VKAPI_ATTR VkResult VKAPI_CALL withoutPushDescriptor(VkPhysicalDevice device, const char* layer,
                                                     uint32_t* count,
                                                     VkExtensionProperties* properties) {
  uint32_t all = 0;
  VkResult r = realEnumerateDeviceExtensions(device, layer, &all, nullptr);
  if (r != VK_SUCCESS) return r;
  std::vector<VkExtensionProperties> list(all);
  r = realEnumerateDeviceExtensions(device, layer, &all, list.data());
  if (r != VK_SUCCESS && r != VK_INCOMPLETE) return r;
  list.resize(all);
  std::vector<VkExtensionProperties> kept;
  for (const auto& e : list)
    if (std::strcmp(e.extensionName, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME) != 0) kept.push_back(e);
  if (!properties) {
    *count = uint32_t(kept.size());
    return VK_SUCCESS;
  }
  uint32_t n = std::min<uint32_t>(*count, uint32_t(kept.size()));
  std::memcpy(properties, kept.data(), n * sizeof(VkExtensionProperties));
  *count = n;
  return n < kept.size() ? VK_INCOMPLETE : VK_SUCCESS;
}

}  // namespace

void injectInstanceFaults(InstanceTable& table) {
  const FaultSpec& f = faultSpec();
  if (f.kind == "no-device") table.vkEnumeratePhysicalDevices = noPhysicalDevices;
  if (f.kind == "no-push-descriptor") {
    realEnumerateDeviceExtensions = table.vkEnumerateDeviceExtensionProperties;
    table.vkEnumerateDeviceExtensionProperties = withoutPushDescriptor;
  }
}

void injectDeviceFaults(DeviceTable& table) {
  const FaultSpec& f = faultSpec();
  if (f.kind == "alloc") {
    realAllocateMemory = table.vkAllocateMemory;
    allocCountdown = f.nth;
    table.vkAllocateMemory = failingAllocateMemory;
  }
  if (f.kind == "device-lost") {
    realQueueSubmit = table.vkQueueSubmit;
    submitCountdown = f.nth;
    table.vkQueueSubmit = losingQueueSubmit;
  }
}

}  // namespace tessera::vk
