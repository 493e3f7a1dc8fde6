#include "vk/async_submission.h"

#include "vk/errors.h"
#include "vk/loader.h"
#include "vk/one_time_commands.h"

namespace tessera::vk {

AsyncSubmission::AsyncSubmission(Context& context) : context_(context) {
  const DeviceTable& vk = context.vk();
  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  poolInfo.queueFamilyIndex = context.queueFamily();
  VK_CHECK(vk.vkCreateCommandPool(context.device(), &poolInfo, nullptr, &pool_));
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  const VkResult fence = vk.vkCreateFence(context.device(), &fenceInfo, nullptr, &fence_);
  if (fence != VK_SUCCESS) {
    vk.vkDestroyCommandPool(context.device(), pool_, nullptr);
    VK_CHECK(fence);
  }
}

AsyncSubmission::~AsyncSubmission() {
  const DeviceTable& vk = context_.vk();
  // The pool's command buffer may not be freed while the queue still runs it.
  if (pending_) vk.vkWaitForFences(context_.device(), 1, &fence_, VK_TRUE, UINT64_MAX);
  vk.vkDestroyFence(context_.device(), fence_, nullptr);
  vk.vkDestroyCommandPool(context_.device(), pool_, nullptr);
}

void AsyncSubmission::submit(const std::function<void(VkCommandBuffer)>& record) {
  wait();
  recordAndSubmit(context_.vk(), context_.device(), context_.queue(), pool_, buffer_, fence_,
                  record);
  pending_ = true;
}

void AsyncSubmission::wait() {
  if (!pending_) return;
  pending_ = false;  // a failed wait (device lost) leaves nothing to wait for again
  VK_CHECK(context_.vk().vkWaitForFences(context_.device(), 1, &fence_, VK_TRUE, UINT64_MAX));
}

}  // namespace tessera::vk
