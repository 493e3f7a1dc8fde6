// The Vulkan backend of DivisionCounter: one dispatch of shaders/division_count.comp.glsl,
// one invocation per patch.
#include <cstdint>  // before the generated SPIR-V array, which uses uint32_t

#include "division/counter.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

#include "division_count_comp.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"

namespace tessera {
namespace {

class VulkanDivisionCounter final : public DivisionCounter {
 public:
  explicit VulkanDivisionCounter(vk::Context& context)
      : context_(context),
        pipeline_(context, {"division_count.comp", kSpirv_division_count_comp,
                            sizeof(kSpirv_division_count_comp), 3, sizeof(gpu::DivisionPush),
                            {}}) {}

  std::vector<gpu::DivisionResult> count(const DivisionBatch& batch,
                                         const DivisionOptions& options) override {
    const gpu::DivisionPush push = divisionPush(options, batch.patches.size());
    std::vector<gpu::DivisionResult> out;
    if (batch.patches.empty()) return out;
    // Buffers only grow, so repeated batches (the benchmark) reuse them.
    ensure(patches_, batch.patches.size() * sizeof(gpu::DivisionPatch), vk::BufferUse::Upload);
    ensure(points_, batch.points.size() * sizeof(gpu::vec4), vk::BufferUse::Upload);
    ensure(results_, batch.patches.size() * sizeof(gpu::DivisionResult), vk::BufferUse::Readback);
    patches_.upload(batch.patches.data(), batch.patches.size() * sizeof(gpu::DivisionPatch));
    points_.upload(batch.points.data(), batch.points.size() * sizeof(gpu::vec4));
    context_.submitAndWait([&](VkCommandBuffer cmd) {
      pipeline_.dispatch(cmd, {&patches_, &points_, &results_}, &push, push.patchCount);
      vk::computeToHostBarrier(context_, cmd);
    });
    results_.download(out, batch.patches.size());
    return out;
  }

 private:
  void ensure(vk::Buffer& buffer, size_t bytes, vk::BufferUse use) {
    vk::requireStorageRange(context_, bytes, "division counts");
    vk::ensureCapacity(context_, buffer, std::max<size_t>(bytes, 16), use);
  }

  vk::Context& context_;
  vk::ComputePipeline pipeline_;
  vk::Buffer patches_, points_, results_;
};

}  // namespace

std::unique_ptr<DivisionCounter> makeVulkanDivisionCounter(vk::Context& context) {
  return std::make_unique<VulkanDivisionCounter>(context);
}

}  // namespace tessera
