// One command buffer submitted without waiting, on the context's queue, with its own pool and
// fence: what a caller records now and reads later, after the submissions it makes meanwhile
// (the trim pass's dispatch, submitted before the level's classification and read after it:
// the queue runs them in order, so one wait covers both; bench/HISTORY.md, "Trimmed faces on
// Vulkan"). Used from the thread that uses the context.
#pragma once
#include "vk/backend_only.h"

#include <functional>

#include "vk/context.h"

namespace tessera::vk {

class AsyncSubmission {
 public:
  explicit AsyncSubmission(Context& context);
  ~AsyncSubmission();  // waits for a submission still pending
  AsyncSubmission(const AsyncSubmission&) = delete;
  AsyncSubmission& operator=(const AsyncSubmission&) = delete;

  // Records `record` and submits it; waits first for a submission still pending.
  void submit(const std::function<void(VkCommandBuffer)>& record);
  // Waits until the last submission has completed (at once if none is pending).
  void wait();
  bool pending() const { return pending_; }

 private:
  Context& context_;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer buffer_ = VK_NULL_HANDLE;  // pool_'s one (recordAndSubmit)
  VkFence fence_ = VK_NULL_HANDLE;
  bool pending_ = false;
};

}  // namespace tessera::vk
