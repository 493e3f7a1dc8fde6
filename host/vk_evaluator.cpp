// The Vulkan backend of PatchEvaluator: one dispatch of shaders/eval.comp.glsl per call,
// buffers kept and grown between calls.
#include <cstdint>  // before the generated SPIR-V array, which uses uint32_t

#include "eval_comp.h"
#include "evaluator.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"

namespace tessera {
namespace {

class VulkanEvaluator final : public PatchEvaluator {
 public:
  explicit VulkanEvaluator(vk::Context& context)
      : context_(context),
        pipeline_(context, {"eval.comp", kSpirv_eval_comp, sizeof(kSpirv_eval_comp), 3,
                            sizeof(gpu::EvalPush), {}}) {}

  std::string name() const override { return "vulkan:" + context_.info().name; }

  std::vector<gpu::EvalSample> evaluate(const std::vector<gpu::BicubicPatch>& patches,
                                        const std::vector<gpu::EvalQuery>& queries) override {
    checkQueries(patches.size(), queries);
    std::vector<gpu::EvalSample> out;
    if (queries.empty()) return out;
    vk::ensureCapacity(context_, patches_, patches.size() * sizeof(gpu::BicubicPatch),
                       vk::BufferUse::Upload);
    vk::ensureCapacity(context_, queries_, queries.size() * sizeof(gpu::EvalQuery),
                       vk::BufferUse::Upload);
    vk::ensureCapacity(context_, samples_, queries.size() * sizeof(gpu::EvalSample),
                       vk::BufferUse::Readback);
    patches_.upload(patches);
    queries_.upload(queries);
    gpu::EvalPush push{static_cast<uint32_t>(queries.size()), kDegenerateEpsFp32, 0, 0};
    context_.submitAndWait([&](VkCommandBuffer cmd) {
      pipeline_.dispatch(cmd, {&patches_, &queries_, &samples_}, &push, push.queryCount);
      vk::computeToHostBarrier(context_, cmd);
    });
    samples_.download(out, queries.size());
    return out;
  }

 private:
  vk::Context& context_;
  vk::ComputePipeline pipeline_;
  vk::Buffer patches_;
  vk::Buffer queries_;
  vk::Buffer samples_;
};

}  // namespace

std::unique_ptr<PatchEvaluator> makeVulkanEvaluator(vk::Context& context) {
  return std::make_unique<VulkanEvaluator>(context);
}

}  // namespace tessera
