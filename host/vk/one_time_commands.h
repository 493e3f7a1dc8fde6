// One one-time command buffer: the pool reset, the buffer recorded by the caller's function and
// submitted to the queue with the fence reset first, to be signalled when the queue has run it.
// Shared by Context::submitAndWait (which then waits) and AsyncSubmission (which waits later).
// `buffer` is the pool's one command buffer, allocated at the first call and recorded again at
// every later one: a pool reset keeps its buffers, so one allocated per call would pile up and
// every reset would walk them all (on lavapipe each reset cleared ~1.2 KB per buffer ever
// allocated: bench/HISTORY.md, "Timestamps and the command pool on lavapipe").
#pragma once
#include "vk/backend_only.h"

#include <functional>

#include "vk/loader.h"

namespace tessera::vk {

void recordAndSubmit(const DeviceTable& vk, VkDevice device, VkQueue queue, VkCommandPool pool,
                     VkCommandBuffer& buffer, VkFence fence,
                     const std::function<void(VkCommandBuffer)>& record);

}  // namespace tessera::vk
