// The library's exceptions as the public API's (include/tessera/errors.h), for its entry points.
#pragma once
#include <stdexcept>
#include <string>

#include <tessera/errors.h>

#include "vk/errors.h"

namespace tessera::api {

// Runs `work`, turning the library's std::invalid_argument (a patch or option it cannot take)
// and Vulkan failures into the public exception types.
template <class Work>
auto translatingErrors(Work&& work) -> decltype(work()) {
  try {
    return work();
  } catch (const std::invalid_argument& e) {
    throw ArgumentError(e.what());
  } catch (const vk::VulkanUnavailable& e) {
    throw DeviceError(std::string("no usable Vulkan device: ") + e.what());
  } catch (const vk::VulkanError& e) {
    throw DeviceError(std::string("the Vulkan device failed: ") + e.what());
  }
}

}  // namespace tessera::api
