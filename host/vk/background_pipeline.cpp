#include "vk/background_pipeline.h"

#include <chrono>
#include <utility>

#include "common/thread_cap.h"

namespace tessera::vk {

BackgroundPipeline::BackgroundPipeline(Context& context, ComputePipelineDesc desc)
    : context_(context), desc_(std::move(desc)) {}

BackgroundPipeline::~BackgroundPipeline() {
  if (pending_.valid()) pending_.wait();
}

void BackgroundPipeline::start() {
  if (pipeline_ || pending_.valid()) return;
  if (!helperThreadsAllowed()) return;  // get() builds it on the caller's thread
  pending_ = std::async(std::launch::async, [this] {
    return std::make_unique<ComputePipeline>(context_, desc_);
  });
}

ComputePipeline& BackgroundPipeline::get() {
  if (!pipeline_) {
    // get() leaves pending_ invalid, so a failed build is tried again next time.
    pipeline_ = pending_.valid() ? pending_.get() : std::make_unique<ComputePipeline>(context_, desc_);
  }
  return *pipeline_;
}

ComputePipeline* BackgroundPipeline::ifReady() {
  const bool finished =
      pending_.valid() && pending_.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
  if (!pipeline_ && finished) pipeline_ = pending_.get();
  return pipeline_.get();
}

}  // namespace tessera::vk
