#include "vk/one_time_commands.h"

#include "vk/errors.h"

namespace tessera::vk {

void recordAndSubmit(const DeviceTable& vk, VkDevice device, VkQueue queue, VkCommandPool pool,
                     VkCommandBuffer& buffer, VkFence fence,
                     const std::function<void(VkCommandBuffer)>& record) {
  VK_CHECK(vk.vkResetCommandPool(device, pool, 0));
  if (buffer == VK_NULL_HANDLE) {
    VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocInfo.commandPool = pool;
    allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocInfo.commandBufferCount = 1;
    VK_CHECK(vk.vkAllocateCommandBuffers(device, &allocInfo, &buffer));
  }
  const VkCommandBuffer cmd = buffer;
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vk.vkBeginCommandBuffer(cmd, &begin));
  record(cmd);
  VK_CHECK(vk.vkEndCommandBuffer(cmd));
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  VK_CHECK(vk.vkResetFences(device, 1, &fence));
  VK_CHECK(vk.vkQueueSubmit(queue, 1, &submit, fence));
}

}  // namespace tessera::vk
