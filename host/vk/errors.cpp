#include "vk/errors.h"

namespace tessera::vk {

const char* resultName(VkResult result) {
  switch (result) {
#define TESSERA_RESULT_CASE(r) \
  case r:                      \
    return #r;
    TESSERA_RESULT_CASE(VK_SUCCESS)
    TESSERA_RESULT_CASE(VK_NOT_READY)
    TESSERA_RESULT_CASE(VK_TIMEOUT)
    TESSERA_RESULT_CASE(VK_INCOMPLETE)
    TESSERA_RESULT_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    TESSERA_RESULT_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    TESSERA_RESULT_CASE(VK_ERROR_INITIALIZATION_FAILED)
    TESSERA_RESULT_CASE(VK_ERROR_DEVICE_LOST)
    TESSERA_RESULT_CASE(VK_ERROR_MEMORY_MAP_FAILED)
    TESSERA_RESULT_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    TESSERA_RESULT_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    TESSERA_RESULT_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    TESSERA_RESULT_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    TESSERA_RESULT_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    TESSERA_RESULT_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    TESSERA_RESULT_CASE(VK_ERROR_FRAGMENTED_POOL)
    TESSERA_RESULT_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
    TESSERA_RESULT_CASE(VK_ERROR_UNKNOWN)
#undef TESSERA_RESULT_CASE
    default:
      return "VkResult(unknown)";
  }
}

VulkanError::VulkanError(const std::string& call, VkResult result)
    : std::runtime_error(call + " failed: " + resultName(result)), result_(result) {}

void throwIfFailed(VkResult result, const char* call) {
  if (result != VK_SUCCESS) throw VulkanError(call, result);
}

}  // namespace tessera::vk
