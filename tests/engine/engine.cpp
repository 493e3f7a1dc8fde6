// An engine that has its own Vulkan, linked with libtessera.a as a user links it
// (tests/engine/CMakeLists.txt builds it twice):
//   ENGINE_USES_VOLK 0: the engine links the Vulkan loader (libvulkan.so) and calls its
//     prototypes;
//   ENGINE_USES_VOLK 1: the engine compiles its own volk.c, as many engines do.
// Tessera compiles volk too, with its names renamed (third_party/CMakeLists.txt): before that,
// the first engine crashed on its first Vulkan call (it reached Tessera's volk pointer, still
// null, instead of the loader's function).
// The engine makes its instance (with the validation layer where installed: any warning or
// error fails), lists its devices, lets Tessera mesh the teapot on Vulkan, lists its devices
// again through its own instance, and checks Tessera's mesh: on lavapipe equal to the CPU
// path's bit for bit, elsewhere the same triangle count within 1%.
//   engine_with_loader|engine_with_volk <teapot.bpt>
#if ENGINE_USES_VOLK
#include <volk.h>
#else
#include <vulkan/vulkan.h>
#endif
#include <tessera/tessera.h>

#include <cstdio>
#include <cstdlib>
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

std::vector<std::string> deviceNames(VkInstance instance) {
  uint32_t count = 0;
  if (vkEnumeratePhysicalDevices(instance, &count, nullptr) != VK_SUCCESS) return {};
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance, &count, devices.data());
  std::vector<std::string> names;
  for (VkPhysicalDevice device : devices) {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(device, &properties);
    names.push_back(properties.deviceName);
  }
  return names;
}

int fail(const char* what) {
  std::fprintf(stderr, "engine: FAILED: %s\n", what);
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) return fail("usage: engine <teapot.bpt>");
#if ENGINE_USES_VOLK
  if (volkInitialize() != VK_SUCCESS) return fail("volkInitialize: no Vulkan loader");
#endif
  uint32_t version = 0;
  if (vkEnumerateInstanceVersion(&version) != VK_SUCCESS || version < VK_API_VERSION_1_1)
    return fail("vkEnumerateInstanceVersion: no Vulkan 1.1 loader");

  const char* validation = "VK_LAYER_KHRONOS_validation";
  const bool validate = hasLayer(validation);
  VkDebugUtilsMessengerCreateInfoEXT messengerInfo{};
  messengerInfo.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
  messengerInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                  VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messengerInfo.pfnUserCallback = onMessage;
  VkApplicationInfo app{};
  app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
  app.pApplicationName = "engine";
  app.apiVersion = VK_API_VERSION_1_1;
  const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
  VkInstanceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  info.pNext = validate ? &messengerInfo : nullptr;  // the instance's own creation checked too
  info.pApplicationInfo = &app;
  info.enabledLayerCount = validate ? 1 : 0;
  info.ppEnabledLayerNames = &validation;
  info.enabledExtensionCount = validate ? 1 : 0;
  info.ppEnabledExtensionNames = &extension;
  VkInstance instance = VK_NULL_HANDLE;
  if (vkCreateInstance(&info, nullptr, &instance) != VK_SUCCESS) return fail("vkCreateInstance");
#if ENGINE_USES_VOLK
  volkLoadInstance(instance);
#endif
  const std::vector<std::string> before = deviceNames(instance);
  if (before.empty()) return fail("the engine's instance lists no device");

  int status = 0;
  try {
    const std::vector<tessera::Patch> teapot = tessera::loadPatches(argv[1]);
    tessera::Tessellator gpu({tessera::Device::Vulkan});
    tessera::Tessellator cpu({tessera::Device::Cpu});
    const tessera::Mesh onGpu = gpu.tessellateToTolerance(teapot, 0.01);
    const tessera::Mesh onCpu = cpu.tessellateToTolerance(teapot, 0.01);
    std::printf(
        "engine: %s, validation %s; its devices: %s; tessera on %s: %zu triangles (cpu "
        "%zu)\n",
        ENGINE_USES_VOLK ? "its own volk" : "the Vulkan loader", validate ? "on" : "not installed",
        before.front().c_str(), gpu.deviceName().c_str(), onGpu.triangleCount(),
        onCpu.triangleCount());
    if (!gpu.usesVulkan()) status = fail("tessera did not run on Vulkan");
    if (gpu.deviceName().find("llvmpipe") != std::string::npos) {
      if (onGpu.positions != onCpu.positions || onGpu.indices != onCpu.indices)
        status = fail("lavapipe's mesh is not the CPU path's, bit for bit");
    } else if (std::abs(double(onGpu.triangleCount()) - double(onCpu.triangleCount())) >
               0.01 * double(onCpu.triangleCount())) {
      status = fail("the GPU's triangle count is more than 1% from the CPU's");
    }
  } catch (const tessera::Error& e) {
    std::fprintf(stderr, "engine: tessera: %s\n", e.what());
    status = 1;
  }
  // The engine's Vulkan still answers after Tessera's came and went.
  if (deviceNames(instance) != before) status = fail("the engine's instance changed its answer");
  vkDestroyInstance(instance, nullptr);
  if (validationMessages != 0) status = fail("validation messages on the engine's instance");
  if (status == 0) std::printf("engine: OK\n");
  return status;
}
