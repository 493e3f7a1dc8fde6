// Vulkan entry points through volk (Debian libvulkan-volk-dev), plus what Tessera adds on top:
// the path of libvulkan.so.1 can be overridden, a missing loader is a VulkanUnavailable with
// instructions, and every table passes through fault injection (vk/fault_injection.h).
//
//   global functions (vkCreateInstance, vkEnumerateInstance*): volk's globals, set once per
//     process by ensureLoaded() and only read afterwards.
//   instance functions: our own InstanceTable per instance, not volk's globals, because
//     volkLoadInstance* overwrites process-wide pointers: two contexts (two instances, maybe on
//     two threads) would race on them and fault wrappers could not be per instance.
//   device functions: volk's VolkDeviceTable per device (volkLoadDeviceTable), fetched from the
//     driver through vkGetDeviceProcAddr, so calls skip the loader's trampoline.
//
// Private to the Vulkan backend's own sources: volk.h declares every Vulkan command as a global
// function pointer, which needs VK_NO_PROTOTYPES in the whole translation unit. tessera_vulkan
// compiles with it (tessera::volk, linked PRIVATE); the other vk/ headers, which its users (the
// CLI, tests, bench) include, only forward-declare the tables, so users never need the macro.
#pragma once
#include "vk/backend_only.h"
#if !defined(VK_NO_PROTOTYPES)
#error "vk/loader.h is private to tessera_vulkan's sources (tessera::volk defines VK_NO_PROTOTYPES)"
#endif
#include <volk.h>

#include <string>

namespace tessera::vk {

#define TESSERA_VK_INSTANCE_FUNCTIONS(X)        \
  X(vkDestroyInstance)                          \
  X(vkEnumeratePhysicalDevices)                 \
  X(vkGetPhysicalDeviceProperties)              \
  X(vkGetPhysicalDeviceProperties2)             \
  X(vkGetPhysicalDeviceFeatures)                \
  X(vkGetPhysicalDeviceQueueFamilyProperties)   \
  X(vkGetPhysicalDeviceMemoryProperties)        \
  X(vkGetPhysicalDeviceFormatProperties)        \
  X(vkEnumerateDeviceExtensionProperties)       \
  X(vkCreateDevice)                             \
  X(vkGetDeviceProcAddr)

// Optional instance functions (extensions): null when the extension is absent.
#define TESSERA_VK_INSTANCE_EXT_FUNCTIONS(X) \
  X(vkCreateDebugUtilsMessengerEXT)          \
  X(vkDestroyDebugUtilsMessengerEXT)

#define TESSERA_VK_DECLARE_MEMBER(name) PFN_##name name = nullptr;

struct InstanceTable {
  TESSERA_VK_INSTANCE_FUNCTIONS(TESSERA_VK_DECLARE_MEMBER)
  TESSERA_VK_INSTANCE_EXT_FUNCTIONS(TESSERA_VK_DECLARE_MEMBER)
};

// volk's table of every device function (null where the device lacks it); a struct of its own
// so that vk/context.h can forward-declare it.
struct DeviceTable : VolkDeviceTable {};

// Opens the Vulkan loader once per process (thread-safe) and hands its vkGetInstanceProcAddr to
// volk (volkInitializeCustom), which sets the global functions. The library is libvulkan.so.1
// unless TESSERA_VULKAN_LOADER names another file. Throws VulkanUnavailable with instructions
// when the loader cannot be opened (every call, not only the first).
void ensureLoaded();

InstanceTable loadInstanceTable(VkInstance instance);
DeviceTable loadDeviceTable(VkInstance instance, VkDevice device);

}  // namespace tessera::vk
