// A compute pipeline made on a worker thread while the caller does other work: the driver
// compiles the shader in vkCreateComputePipelines (tens of milliseconds on lavapipe, at every
// run: it keeps no pipeline cache), so a pipeline needed later (the vertex evaluation after
// the quad-tree) need not wait its turn. Vulkan lets creation calls on one device run
// concurrently with submissions; the pipeline cache is internally synchronized.
#pragma once
#include "vk/backend_only.h"
#include <future>
#include <memory>

#include "vk/pipeline.h"

namespace tessera::vk {

class BackgroundPipeline {
 public:
  BackgroundPipeline(Context& context, ComputePipelineDesc desc);
  // Waits for a build still running (its pipeline, or error, is dropped).
  ~BackgroundPipeline();
  BackgroundPipeline(const BackgroundPipeline&) = delete;
  BackgroundPipeline& operator=(const BackgroundPipeline&) = delete;

  // Starts building on a worker thread; no effect once started or built, or under a thread
  // cap of 1 (common/thread_cap.h: get() then builds it on the caller's thread).
  void start();
  // The pipeline: waits for the build started by start(), or builds it now. Rethrows the
  // build's error (VulkanError) and builds again on the next call.
  ComputePipeline& get();
  // The pipeline if its build has finished, else nullptr: never waits and never builds (so
  // nullptr until a build start() began ends; always, where it began none under a cap of 1).
  // Rethrows a failed build's error as get() does.
  ComputePipeline* ifReady();

 private:
  Context& context_;
  ComputePipelineDesc desc_;
  std::future<std::unique_ptr<ComputePipeline>> pending_;
  std::unique_ptr<ComputePipeline> pipeline_;
};

}  // namespace tessera::vk
