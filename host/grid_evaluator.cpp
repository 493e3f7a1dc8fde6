// The backends of GridEvaluator: the fp32 mirror (rows shared out to threads) and Vulkan (one
// dispatch, one invocation per row, buffers kept and grown between calls).
#include <cstdint>  // before the generated SPIR-V array, which uses uint32_t

#include "grid_evaluator.h"

#include <algorithm>
#include <stdexcept>
#include <thread>

#include "evaluator.h"
#include "grid_eval_comp.h"
#include "mirror/grid_mirror.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"

namespace tessera {
namespace {

void checkPointsPerSide(uint32_t pointsPerSide) {
  if (pointsPerSide < 2)
    throw std::invalid_argument("grid evaluation: points per side must be >= 2, got " +
                                std::to_string(pointsPerSide));
}

class MirrorGridEvaluator final : public GridEvaluator {
 public:
  explicit MirrorGridEvaluator(unsigned threads)
      : threads_(threads ? threads : std::max(1u, std::thread::hardware_concurrency())) {}

  std::string name() const override {
    return threads_ == 1 ? "mirror" : "mirror x" + std::to_string(threads_);
  }

  const gpu::GridVertex* evaluate(const std::vector<gpu::BicubicPatch>& patches,
                                  uint32_t pointsPerSide) override {
    checkPointsPerSide(pointsPerSide);
    out_.resize(gridVertexCount(patches.size(), pointsPerSide));
    const size_t rows = patches.size() * pointsPerSide;
    auto work = [&](size_t first, size_t last) {
      for (size_t r = first; r < last; ++r)
        mirror::evalGridRow(patches[r / pointsPerSide], uint32_t(r % pointsPerSide),
                            pointsPerSide, kDegenerateEpsFp32, &out_[r * pointsPerSide]);
    };
    if (threads_ == 1 || rows < 2) {
      work(0, rows);
      return out_.data();
    }
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads_; ++t)
      pool.emplace_back(work, rows * t / threads_, rows * (t + 1) / threads_);
    for (auto& thread : pool) thread.join();
    return out_.data();
  }

 private:
  unsigned threads_;
  std::vector<gpu::GridVertex> out_;
};

class VulkanGridEvaluator final : public GridEvaluator {
 public:
  explicit VulkanGridEvaluator(vk::Context& context)
      : context_(context),
        pipeline_(context, {"grid_eval.comp", kSpirv_grid_eval_comp, sizeof(kSpirv_grid_eval_comp),
                            2, sizeof(gpu::GridEvalPush), {}}) {}

  std::string name() const override { return "vulkan:" + context_.info().name; }

  const gpu::GridVertex* evaluate(const std::vector<gpu::BicubicPatch>& patches,
                                  uint32_t pointsPerSide) override {
    checkPointsPerSide(pointsPerSide);
    const size_t bytes = gridVertexCount(patches.size(), pointsPerSide) * sizeof(gpu::GridVertex);
    const uint64_t limit = context_.info().maxStorageBufferRange;
    if (limit && bytes > limit)
      throw std::length_error("grid evaluation: " + std::to_string(bytes) +
                              " bytes of vertices exceed the device's storage buffer range of " +
                              std::to_string(limit));
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

std::unique_ptr<GridEvaluator> makeMirrorGridEvaluator(unsigned threads) {
  return std::make_unique<MirrorGridEvaluator>(threads);
}

std::unique_ptr<GridEvaluator> makeVulkanGridEvaluator(vk::Context& context) {
  return std::make_unique<VulkanGridEvaluator>(context);
}

}  // namespace tessera
