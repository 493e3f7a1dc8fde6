// One one-time command buffer: the pool reset, the buffer recorded by the caller's function and
// submitted to the queue with the fence reset first, to be signalled when the queue has run it.
// Shared by Context::submitAndWait (which then waits) and AsyncSubmission (which waits later).
#pragma once
#include "vk/backend_only.h"

#include <functional>

#include "vk/loader.h"

namespace tessera::vk {

void recordAndSubmit(const DeviceTable& vk, VkDevice device, VkQueue queue, VkCommandPool pool,
                     VkFence fence, const std::function<void(VkCommandBuffer)>& record);

}  // namespace tessera::vk
