// A small volk-style meta-loader: libvulkan.so.1 is opened at run time (no link-time
// dependency), global and instance entry points are fetched through vkGetInstanceProcAddr and
// device entry points straight from the driver through vkGetDeviceProcAddr, into tables.
// Device functions live in a per-device table (not globals) so that two contexts can live
// side by side, and so that tests can wrap single entry points to inject faults.
#pragma once
#include "vk/backend_only.h"
#include <vulkan/vulkan.h>

#include <string>

namespace tessera::vk {

#define TESSERA_VK_GLOBAL_FUNCTIONS(X)    \
  X(vkCreateInstance)                     \
  X(vkEnumerateInstanceExtensionProperties) \
  X(vkEnumerateInstanceLayerProperties)   \
  X(vkEnumerateInstanceVersion)

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

#define TESSERA_VK_DEVICE_FUNCTIONS(X)     \
  X(vkDestroyDevice)                       \
  X(vkGetDeviceQueue)                      \
  X(vkDeviceWaitIdle)                      \
  X(vkQueueSubmit)                         \
  X(vkQueueWaitIdle)                       \
  X(vkCreateBuffer)                        \
  X(vkDestroyBuffer)                       \
  X(vkGetBufferMemoryRequirements)         \
  X(vkAllocateMemory)                      \
  X(vkFreeMemory)                          \
  X(vkBindBufferMemory)                    \
  X(vkMapMemory)                           \
  X(vkUnmapMemory)                         \
  X(vkCreateImage)                         \
  X(vkDestroyImage)                        \
  X(vkGetImageMemoryRequirements)          \
  X(vkBindImageMemory)                     \
  X(vkCreateImageView)                     \
  X(vkDestroyImageView)                    \
  X(vkCreateShaderModule)                  \
  X(vkDestroyShaderModule)                 \
  X(vkCreatePipelineCache)                 \
  X(vkDestroyPipelineCache)                \
  X(vkGetPipelineCacheData)                \
  X(vkCreateComputePipelines)              \
  X(vkCreateGraphicsPipelines)             \
  X(vkDestroyPipeline)                     \
  X(vkCreatePipelineLayout)                \
  X(vkDestroyPipelineLayout)               \
  X(vkCreateDescriptorSetLayout)           \
  X(vkDestroyDescriptorSetLayout)          \
  X(vkCreateRenderPass)                    \
  X(vkDestroyRenderPass)                   \
  X(vkCreateFramebuffer)                   \
  X(vkDestroyFramebuffer)                  \
  X(vkCreateCommandPool)                   \
  X(vkDestroyCommandPool)                  \
  X(vkResetCommandPool)                    \
  X(vkAllocateCommandBuffers)              \
  X(vkBeginCommandBuffer)                  \
  X(vkEndCommandBuffer)                    \
  X(vkCreateFence)                         \
  X(vkDestroyFence)                        \
  X(vkResetFences)                         \
  X(vkWaitForFences)                       \
  X(vkCreateQueryPool)                     \
  X(vkDestroyQueryPool)                    \
  X(vkGetQueryPoolResults)                 \
  X(vkCmdResetQueryPool)                   \
  X(vkCmdWriteTimestamp)                   \
  X(vkCmdBindPipeline)                     \
  X(vkCmdPushConstants)                    \
  X(vkCmdDispatch)                         \
  X(vkCmdPipelineBarrier)                  \
  X(vkCmdCopyBuffer)                       \
  X(vkCmdCopyImageToBuffer)                \
  X(vkCmdFillBuffer)                       \
  X(vkCmdBeginRenderPass)                  \
  X(vkCmdEndRenderPass)                    \
  X(vkCmdBindVertexBuffers)                \
  X(vkCmdBindIndexBuffer)                  \
  X(vkCmdDrawIndexed)                      \
  X(vkCmdSetViewport)                      \
  X(vkCmdSetScissor)                       \
  X(vkCmdBeginQuery)                       \
  X(vkCmdEndQuery)                         \
  X(vkCmdDraw)

// Optional device functions (extensions): null when absent.
#define TESSERA_VK_DEVICE_EXT_FUNCTIONS(X) X(vkCmdPushDescriptorSetKHR)

#define TESSERA_VK_DECLARE_MEMBER(name) PFN_##name name = nullptr;

struct GlobalTable {
  PFN_vkGetInstanceProcAddr vkGetInstanceProcAddr = nullptr;
  TESSERA_VK_GLOBAL_FUNCTIONS(TESSERA_VK_DECLARE_MEMBER)
};

struct InstanceTable {
  TESSERA_VK_INSTANCE_FUNCTIONS(TESSERA_VK_DECLARE_MEMBER)
  TESSERA_VK_INSTANCE_EXT_FUNCTIONS(TESSERA_VK_DECLARE_MEMBER)
};

struct DeviceTable {
  TESSERA_VK_DEVICE_FUNCTIONS(TESSERA_VK_DECLARE_MEMBER)
  TESSERA_VK_DEVICE_EXT_FUNCTIONS(TESSERA_VK_DECLARE_MEMBER)
};

// Opens the Vulkan loader once per process (thread-safe) and returns its global table.
// The library path is libvulkan.so.1 unless TESSERA_VULKAN_LOADER names another file.
// Throws VulkanUnavailable with instructions when the loader cannot be opened.
const GlobalTable& globalTable();

InstanceTable loadInstanceTable(const GlobalTable& global, VkInstance instance);
DeviceTable loadDeviceTable(const InstanceTable& instance, VkDevice device);

// The library path globalTable() opened (or tried to open).
std::string loaderPath();

}  // namespace tessera::vk
