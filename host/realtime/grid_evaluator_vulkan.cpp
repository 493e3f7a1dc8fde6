// The Vulkan backend of GridEvaluator: one dispatch of shaders/grid_eval.comp.glsl, one
// invocation per row, buffers kept and grown between calls.
#include <cstdint>  // before the generated SPIR-V array, which uses uint32_t

#include "realtime/grid_evaluator.h"

#include <stdexcept>
#include <string>

#include "eval/evaluator.h"
#include "grid_eval_comp.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"

namespace tessera {
namespace {

class VulkanGridEvaluator final : public GridEvaluator {
 public:
  explicit VulkanGridEvaluator(vk::Context& context)
      : context_(context),
        pipeline_(context, {"grid_eval.comp", kSpirv_grid_eval_comp, sizeof(kSpirv_grid_eval_comp),
                            2, sizeof(gpu::GridEvalPush), {}}) {}

  std::string name() const override { return "vulkan:" + context_.info().name; }

  const gpu::GridVertex* evaluate(const std::vector<gpu::BicubicPatch>& patches,
                                  uint32_t pointsPerSide) override {
    validateGridPointsPerSide(pointsPerSide);
    const size_t bytes = gridVertexCount(patches.size(), pointsPerSide) * sizeof(gpu::GridVertex);
    vk::requireStorageRange(context_, bytes, "grid evaluation (vertices)");
    if (patches.empty()) return nullptr;
    vk::ensureCapacity(context_, patches_, patches.size() * sizeof(gpu::BicubicPatch),
                       vk::BufferUse::Upload);
    vk::ensureCapacity(context_, vertices_, bytes, vk::BufferUse::Readback);
    patches_.upload(patches);
    gpu::GridEvalPush push{uint32_t(patches.size()), pointsPerSide, kDegenerateEpsFp32, 0};
    context_.submitAndWait([&](VkCommandBuffer cmd) {
      pipeline_.dispatch(cmd, {&patches_, &vertices_}, &push, push.patchCount * pointsPerSide);
      vk::computeToHostBarrier(context_, cmd);
    });
    return vertices_.as<gpu::GridVertex>();
  }

 private:
  vk::Context& context_;
  vk::ComputePipeline pipeline_;
  vk::Buffer patches_;
  vk::Buffer vertices_;
};

}  // namespace

std::unique_ptr<GridEvaluator> makeVulkanGridEvaluator(vk::Context& context) {
  return std::make_unique<VulkanGridEvaluator>(context);
}

}  // namespace tessera
