#include "vk/loader.h"

#include <dlfcn.h>

#include <cstdlib>
#include <mutex>

#include "vk/errors.h"
#include "vk/fault_injection.h"

namespace tessera::vk {
namespace {

std::string chosenLoaderPath() {
  const char* overridePath = std::getenv("TESSERA_VULKAN_LOADER");
  return (overridePath && *overridePath) ? overridePath : "libvulkan.so.1";
}

}  // namespace

std::string loaderPath() { return chosenLoaderPath(); }

const GlobalTable& globalTable() {
  static GlobalTable table;
  static std::string failure;
  static std::once_flag once;
  std::call_once(once, [] {
    const std::string path = chosenLoaderPath();
    // The handle is never closed: function pointers from it live as long as the process.
    void* library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!library) {
      const char* why = dlerror();
      failure = "cannot open the Vulkan loader '" + path + "' (" + (why ? why : "unknown") +
                "). Install it with `apt-get install libvulkan1 mesa-vulkan-drivers`, or run "
                "with `--backend cpu`.";
      return;
    }
    table.vkGetInstanceProcAddr =
        reinterpret_cast<PFN_vkGetInstanceProcAddr>(dlsym(library, "vkGetInstanceProcAddr"));
    if (!table.vkGetInstanceProcAddr) {
      failure = "'" + path + "' is not a Vulkan loader (no vkGetInstanceProcAddr)";
      return;
    }
#define TESSERA_LOAD_GLOBAL(name) \
  table.name = reinterpret_cast<PFN_##name>(table.vkGetInstanceProcAddr(nullptr, #name));
    TESSERA_VK_GLOBAL_FUNCTIONS(TESSERA_LOAD_GLOBAL)
#undef TESSERA_LOAD_GLOBAL
    if (!table.vkCreateInstance) failure = "the Vulkan loader '" + path + "' lacks vkCreateInstance";
  });
  if (!failure.empty()) throw VulkanUnavailable(failure);
  return table;
}

InstanceTable loadInstanceTable(const GlobalTable& global, VkInstance instance) {
  InstanceTable table;
#define TESSERA_LOAD_INSTANCE(name) \
  table.name = reinterpret_cast<PFN_##name>(global.vkGetInstanceProcAddr(instance, #name));
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

DeviceTable loadDeviceTable(const InstanceTable& instance, VkDevice device) {
  DeviceTable table;
  // Fetched from the device itself, so calls skip the loader's trampoline (as volk does).
#define TESSERA_LOAD_DEVICE(name) \
  table.name = reinterpret_cast<PFN_##name>(instance.vkGetDeviceProcAddr(device, #name));
  TESSERA_VK_DEVICE_FUNCTIONS(TESSERA_LOAD_DEVICE)
  TESSERA_VK_DEVICE_EXT_FUNCTIONS(TESSERA_LOAD_DEVICE)
#undef TESSERA_LOAD_DEVICE
#define TESSERA_REQUIRE_DEVICE(name) \
  if (!table.name) throw VulkanUnavailable("the Vulkan device lacks " #name);
  TESSERA_VK_DEVICE_FUNCTIONS(TESSERA_REQUIRE_DEVICE)
#undef TESSERA_REQUIRE_DEVICE
  injectDeviceFaults(table);
  return table;
}

}  // namespace tessera::vk
