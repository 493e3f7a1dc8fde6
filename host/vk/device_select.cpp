#include "vk/device_select.h"

#include <algorithm>
#include <cctype>
#include <cstring>

#include "vk/loader.h"

namespace tessera::vk {

const std::vector<const char*>& requiredDeviceExtensions() {
  // Push descriptors: buffers are bound per dispatch without descriptor pools.
  static const std::vector<const char*> extensions = {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
  return extensions;
}

std::string DeviceInfo::typeName() const {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
    default: return "other";
  }
}

VkInstance createInstance(const std::vector<const char*>& layers,
                          const std::vector<const char*>& extensions, const void* next) {
  ensureLoaded();
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "tessera";
  app.pEngineName = "tessera";
  app.apiVersion = VK_API_VERSION_1_2;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pNext = next;
  info.pApplicationInfo = &app;
  info.enabledLayerCount = static_cast<uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VkInstance instance = VK_NULL_HANDLE;
  VkResult result = vkCreateInstance(&info, nullptr, &instance);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
    throw VulkanUnavailable(
        "no Vulkan driver found (vkCreateInstance: VK_ERROR_INCOMPATIBLE_DRIVER). Install one, "
        "e.g. `apt-get install mesa-vulkan-drivers` for the CPU driver lavapipe, or run with "
        "`--backend cpu`.");
  VK_CHECK(result);
  return instance;
}

DeviceInfo describeDevice(const InstanceTable& vk, VkPhysicalDevice device, uint32_t index) {
  DeviceInfo info;
  info.index = index;
  VkPhysicalDeviceProperties props{};
  vk.vkGetPhysicalDeviceProperties(device, &props);
  info.name = props.deviceName;
  info.type = props.deviceType;
  info.apiVersion = props.apiVersion;
  info.maxStorageBufferRange = props.limits.maxStorageBufferRange;
  info.maxTexelBufferElements = props.limits.maxTexelBufferElements;
  info.maxComputeWorkGroupCountX = props.limits.maxComputeWorkGroupCount[0];
  info.timestampPeriodNs = props.limits.timestampPeriod;

  if (props.apiVersion >= VK_API_VERSION_1_1) {
    VkPhysicalDeviceMaintenance3Properties maintenance3{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 props2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    props2.pNext = &maintenance3;
    const bool driverProperties = props.apiVersion >= VK_API_VERSION_1_2;
    if (driverProperties) maintenance3.pNext = &driver;
    vk.vkGetPhysicalDeviceProperties2(device, &props2);
    info.maxMemoryAllocationSize = maintenance3.maxMemoryAllocationSize;
    if (driverProperties) {
      info.driverId = driver.driverID;
      info.driverName = driver.driverName;
      info.driverInfo = driver.driverInfo;
    }
  }

  if (props.apiVersion < VK_API_VERSION_1_1) {
    info.unusableReason = "Vulkan 1.1 or newer is required";
    return info;
  }
  uint32_t count = 0;
  vk.vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vk.vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data());
  for (const char* required : requiredDeviceExtensions()) {
    bool found = std::any_of(extensions.begin(), extensions.end(), [&](const auto& e) {
      return std::strcmp(e.extensionName, required) == 0;
    });
    if (!found) {
      info.unusableReason = std::string("missing device extension ") + required;
      return info;
    }
  }
  info.usable = true;
  return info;
}

namespace {

int typeRank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 3;
    default: return 4;
  }
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string deviceList(const std::vector<DeviceInfo>& devices) {
  std::string list;
  for (const auto& d : devices) {
    list += "\n  [" + std::to_string(d.index) + "] " + d.name + " (" + d.typeName() + ")";
    if (!d.usable) list += " — unusable: " + d.unusableReason;
  }
  return list.empty() ? "\n  (none)" : list;
}

}  // namespace

size_t selectDevice(const std::vector<DeviceInfo>& devices, const std::string& selector) {
  if (devices.empty())
    throw VulkanUnavailable(
        "no Vulkan device found. Install a driver, e.g. `apt-get install mesa-vulkan-drivers` "
        "for the CPU driver lavapipe, or run with `--backend cpu`.");
  if (!selector.empty()) {
    bool numeric = std::all_of(selector.begin(), selector.end(),
                               [](unsigned char c) { return std::isdigit(c); });
    for (size_t i = 0; i < devices.size(); ++i) {
      bool match = numeric ? std::to_string(devices[i].index) == selector
                           : lower(devices[i].name).find(lower(selector)) != std::string::npos;
      if (!match) continue;
      if (!devices[i].usable)
        throw VulkanUnavailable("device '" + devices[i].name +
                                "' cannot be used: " + devices[i].unusableReason);
      return i;
    }
    throw VulkanUnavailable("no Vulkan device matches '" + selector + "'. Devices:" +
                            deviceList(devices));
  }
  size_t best = devices.size();
  for (size_t i = 0; i < devices.size(); ++i) {
    if (!devices[i].usable) continue;
    if (best == devices.size() || typeRank(devices[i].type) < typeRank(devices[best].type))
      best = i;
  }
  if (best == devices.size())
    throw VulkanUnavailable("no usable Vulkan device. Devices:" + deviceList(devices) +
                            "\nInstall `mesa-vulkan-drivers` or run with `--backend cpu`.");
  return best;
}

std::vector<DeviceInfo> listDevices() {
  VkInstance instance = createInstance({}, {}, nullptr);
  InstanceTable vk = loadInstanceTable(instance);
  uint32_t count = 0;
  vk.vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> physical(count);
  vk.vkEnumeratePhysicalDevices(instance, &count, physical.data());
  std::vector<DeviceInfo> devices;
  for (uint32_t i = 0; i < count; ++i) devices.push_back(describeDevice(vk, physical[i], i));
  vk.vkDestroyInstance(instance, nullptr);
  return devices;
}

}  // namespace tessera::vk
