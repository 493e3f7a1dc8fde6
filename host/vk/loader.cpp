#include "vk/loader.h"

#include <dlfcn.h>

#include <cstdlib>
#include <mutex>

#include "vk/errors.h"
#include "vk/fault_injection.h"
#include "vk/object_census.h"

namespace tessera::vk {

void ensureLoaded() {
  static std::string failure;
  static std::once_flag once;
  std::call_once(once, [] {
    // Opened here rather than by volkInitialize(), which only tries the default names: this is
    // what lets TESSERA_VULKAN_LOADER point elsewhere (the tests simulate a missing loader).
    const char* overridePath = std::getenv("TESSERA_VULKAN_LOADER");
    const std::string path = (overridePath && *overridePath) ? overridePath : "libvulkan.so.1";
    // The handle is never closed: function pointers from it live as long as the process.
    void* library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!library) {
      const char* why = dlerror();
      failure = "cannot open the Vulkan loader '" + path + "' (" + (why ? why : "unknown") +
                "). Install it with `apt-get install libvulkan1 mesa-vulkan-drivers`, or run "
                "with `--backend cpu`.";
      return;
    }
    auto getInstanceProcAddr =
        reinterpret_cast<PFN_vkGetInstanceProcAddr>(dlsym(library, "vkGetInstanceProcAddr"));
    if (!getInstanceProcAddr) {
      failure = "'" + path + "' is not a Vulkan loader (no vkGetInstanceProcAddr)";
      return;
    }
    volkInitializeCustom(getInstanceProcAddr);
    if (!vkCreateInstance || !vkEnumerateInstanceLayerProperties ||
        !vkEnumerateInstanceExtensionProperties)
      failure = "the Vulkan loader '" + path + "' lacks vkCreateInstance";
  });
  if (!failure.empty()) throw VulkanUnavailable(failure);
}

InstanceTable loadInstanceTable(VkInstance instance) {
  InstanceTable table;  // the instance exists, so ensureLoaded() has set vkGetInstanceProcAddr
#define TESSERA_LOAD_INSTANCE(name) \
  table.name = reinterpret_cast<PFN_##name>(vkGetInstanceProcAddr(instance, #name));
  TESSERA_VK_INSTANCE_FUNCTIONS(TESSERA_LOAD_INSTANCE)
  TESSERA_VK_INSTANCE_EXT_FUNCTIONS(TESSERA_LOAD_INSTANCE)
#undef TESSERA_LOAD_INSTANCE
#define TESSERA_REQUIRE_INSTANCE(name) \
  if (!table.name) throw VulkanUnavailable("the Vulkan loader lacks " #name);
  TESSERA_VK_INSTANCE_FUNCTIONS(TESSERA_REQUIRE_INSTANCE)
#undef TESSERA_REQUIRE_INSTANCE
  injectInstanceFaults(table);
  return table;
}

DeviceTable loadDeviceTable(VkInstance instance, VkDevice device) {
  DeviceTable table{};
  {
    // volkLoadDeviceTable fetches through volk's global vkGetDeviceProcAddr, which only
    // volkLoadInstanceOnly sets (with the other instance globals, which we never read). The
    // two calls are one step under a lock, so contexts created on two threads do not race.
    static std::mutex mutex;
    std::lock_guard<std::mutex> lock(mutex);
    volkLoadInstanceOnly(instance);
    volkLoadDeviceTable(&table, device);
  }
  // Vulkan 1.0 guarantees the core functions; an empty table means the loading itself failed.
  if (!table.vkDestroyDevice || !table.vkQueueSubmit)
    throw VulkanUnavailable("could not load the Vulkan device functions (vkGetDeviceProcAddr)");
  injectDeviceFaults(table);
  countObjectsWhileCensusOpen(table);
  return table;
}

}  // namespace tessera::vk
