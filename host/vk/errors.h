// Errors from the Vulkan layer. Every Vulkan call that returns VkResult goes through
// VK_CHECK, which names the call and the result.
#pragma once
#include "vk/backend_only.h"
#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>

namespace tessera::vk {

const char* resultName(VkResult result);

// A Vulkan call failed.
class VulkanError : public std::runtime_error {
 public:
  VulkanError(const std::string& call, VkResult result);
  VkResult result() const { return result_; }

 private:
  VkResult result_;
};

// No usable Vulkan at all (no loader, no device, a missing required feature). The message
// says how to fix it; `--backend auto` falls back to the CPU on this error.
class VulkanUnavailable : public std::runtime_error {
 public:
  explicit VulkanUnavailable(const std::string& message) : std::runtime_error(message) {}
};

void throwIfFailed(VkResult result, const char* call);

}  // namespace tessera::vk

#define VK_CHECK(call) ::tessera::vk::throwIfFailed((call), #call)
