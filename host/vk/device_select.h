// Describing physical devices and choosing one (internal to host/vk/).
#pragma once
#include "vk/backend_only.h"
#include <string>
#include <vector>

#include "vk/context.h"

namespace tessera::vk {

// Fills name, type, driver, limits and whether Tessera can use the device.
DeviceInfo describeDevice(const InstanceTable& vk, VkPhysicalDevice device, uint32_t index);

// Picks from `devices` by `selector` (see ContextOptions::device); throws VulkanUnavailable
// with the list of devices when nothing matches or nothing is usable.
size_t selectDevice(const std::vector<DeviceInfo>& devices, const std::string& selector);

// Device extensions Tessera requires.
const std::vector<const char*>& requiredDeviceExtensions();

// An instance (opening the Vulkan loader first, vk/loader.h); destroyed by the caller.
VkInstance createInstance(const std::vector<const char*>& layers,
                          const std::vector<const char*>& extensions, const void* next);

}  // namespace tessera::vk
