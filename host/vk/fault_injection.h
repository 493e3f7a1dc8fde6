// Faults injected into the dispatch tables of vk/loader.h (wrappers replace table entries), for
// testing the error paths: the environment variable TESSERA_VK_FAULT names one (read once per
// process):
//   alloc[:N]            the N-th vkAllocateMemory (default the first) fails with
//                        VK_ERROR_OUT_OF_DEVICE_MEMORY
//   device-lost[:N]      the N-th vkQueueSubmit fails with VK_ERROR_DEVICE_LOST
//   no-device            vkEnumeratePhysicalDevices reports no devices
//   no-push-descriptor   devices do not list VK_KHR_push_descriptor (a missing feature)
#pragma once
#include "vk/backend_only.h"
#include "vk/loader.h"

namespace tessera::vk {

// Replace entry points in the tables by failing wrappers where TESSERA_VK_FAULT asks.
void injectInstanceFaults(InstanceTable& table);
void injectDeviceFaults(DeviceTable& table);

}  // namespace tessera::vk
