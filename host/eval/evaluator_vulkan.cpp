// The Vulkan backend of PatchEvaluator: one dispatch of shaders/eval.comp.glsl (bicubic) or
// eval_general.comp.glsl (general patches, pipeline made on first use) per call, buffers kept
// and grown between calls.
#include <cstdint>  // before the generated SPIR-V array, which uses uint32_t

#include <memory>

#include "eval_comp.h"
#include "eval_general_comp.h"
#include "eval/evaluator.h"
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

  std::vector<gpu::EvalSample> evaluate(const PatchSet& patches,
                                        const std::vector<gpu::EvalQuery>& queries) override {
    return patches.isBicubic() ? evaluateBicubic(patches.bicubic(), queries)
                               : evaluateGeneral(patches.general(), queries);
  }

 private:
  std::vector<gpu::EvalSample> evaluateBicubic(const std::vector<gpu::BicubicPatch>& patches,
                                               const std::vector<gpu::EvalQuery>& queries) {
    checkQueries(patches.size(), queries);
    if (queries.empty()) return {};
    vk::ensureCapacity(context_, patches_, patches.size() * sizeof(gpu::BicubicPatch),
                       vk::BufferUse::Upload);
    vk::ensureCapacity(context_, queries_, queries.size() * sizeof(gpu::EvalQuery),
                       vk::BufferUse::Upload);
    vk::ensureCapacity(context_, samples_, queries.size() * sizeof(gpu::EvalSample),
                       vk::BufferUse::Readback);
    patches_.upload(patches);
    return run(pipeline_, {&patches_, &queries_, &samples_}, queries);
  }

  std::vector<gpu::EvalSample> evaluateGeneral(const GeneralPatchSet& patches,
                                               const std::vector<gpu::EvalQuery>& queries) {
    checkQueries(patches.size(), queries);
    if (queries.empty()) return {};
    if (!general_)
      general_ = std::make_unique<vk::ComputePipeline>(
          context_, vk::ComputePipelineDesc{"eval_general.comp", kSpirv_eval_general_comp,
                                            sizeof(kSpirv_eval_general_comp), 4,
                                            sizeof(gpu::EvalPush), {}});
    vk::ensureCapacity(context_, patches_, patches.size() * sizeof(gpu::GeneralPatch),
                       vk::BufferUse::Upload);
    vk::ensureCapacity(context_, points_, patches.points.size() * sizeof(gpu::vec4),
                       vk::BufferUse::Upload);
    vk::ensureCapacity(context_, queries_, queries.size() * sizeof(gpu::EvalQuery),
                       vk::BufferUse::Upload);
    vk::ensureCapacity(context_, samples_, queries.size() * sizeof(gpu::EvalSample),
                       vk::BufferUse::Readback);
    patches_.upload(patches.patches);
    points_.upload(patches.points);
    return run(*general_, {&patches_, &queries_, &samples_, &points_}, queries);
  }

  std::vector<gpu::EvalSample> run(vk::ComputePipeline& pipeline,
                                   std::initializer_list<const vk::Buffer*> buffers,
                                   const std::vector<gpu::EvalQuery>& queries) {
    queries_.upload(queries);
    gpu::EvalPush push{static_cast<uint32_t>(queries.size()), kDegenerateEpsFp32, 0, 0};
    context_.submitAndWait([&](VkCommandBuffer cmd) {
      pipeline.dispatch(cmd, buffers, &push, push.queryCount);
      vk::computeToHostBarrier(context_, cmd);
    });
    std::vector<gpu::EvalSample> out;
    samples_.download(out, queries.size());
    return out;
  }

  vk::Context& context_;
  vk::ComputePipeline pipeline_;
  std::unique_ptr<vk::ComputePipeline> general_;
  vk::Buffer points_;
  vk::Buffer patches_;
  vk::Buffer queries_;
  vk::Buffer samples_;
};

}  // namespace

std::unique_ptr<PatchEvaluator> makeVulkanEvaluator(vk::Context& context) {
  return std::make_unique<VulkanEvaluator>(context);
}

}  // namespace tessera
