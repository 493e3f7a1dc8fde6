// The Vulkan backend of StencilEvaluator: the table is uploaded once; each apply() writes the
// control rows into the mapped values buffer, runs one dispatch of
// shaders/loop_stencil.comp.glsl per batch (a compute-to-compute barrier between batches, as
// each level reads the one before), and reads the rows back.
#include <cstdint>  // before the generated SPIR-V array, which uses uint32_t

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "loop/evaluator.h"
#include "loop_stencil_comp.h"
#include "shaders/layout.h"
#include "tessera/errors.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"

namespace tessera {
namespace {

vk::Buffer uploadArray(vk::Context& context, const void* data, size_t bytes) {
  // A zero-sized buffer is invalid; an empty table still binds a small one.
  vk::Buffer buffer(context, std::max<size_t>(bytes, 16), vk::BufferUse::Upload);
  if (bytes) buffer.upload(data, bytes);
  return buffer;
}

class VulkanStencilEvaluator final : public StencilEvaluator {
 public:
  VulkanStencilEvaluator(vk::Context& context, const FloatStencilTable& table, uint32_t width)
      : context_(context),
        pipeline_(context, {"loop_stencil.comp", kSpirv_loop_stencil_comp,
                            sizeof(kSpirv_loop_stencil_comp), 4, sizeof(gpu::LoopStencilPush),
                            {}}),
        timer_(context, 2),
        tableRows_(table.rowCount()),
        sourceRows_(table.sourceRows),
        width_(width),
        batchEnds_(table.batchEnds) {
    if (width == 0) throw std::invalid_argument("stencil evaluator: row width 0");
    const uint64_t valueBytes = uint64_t(table.rowCount()) * width * sizeof(float);
    // Each array is one storage buffer: check every one against the range, and name the one
    // that does not fit (the indices and weights, not the vertex data, overflow first).
    const uint64_t limit = context.info().maxStorageBufferRange;
    const struct { const char* what; uint64_t bytes; } arrays[] = {
        {"vertex data", valueBytes},
        {"stencil offsets", uint64_t(table.offsets.size()) * sizeof(uint32_t)},
        {"stencil indices", uint64_t(table.indices.size()) * sizeof(uint32_t)},
        {"stencil weights", uint64_t(table.weights.size()) * sizeof(float)}};
    for (const auto& array : arrays)
      if (array.bytes > limit)
        throw LimitError("Loop stencils: " + std::to_string(array.bytes) + " bytes of " +
                         array.what + " exceed the device's storage buffer range (" +
                         std::to_string(limit) + " bytes); use fewer levels or --backend cpu");
    offsets_ = uploadArray(context, table.offsets.data(), table.offsets.size() * sizeof(uint32_t));
    indices_ = uploadArray(context, table.indices.data(), table.indices.size() * sizeof(uint32_t));
    weights_ = uploadArray(context, table.weights.data(), table.weights.size() * sizeof(float));
    values_ = vk::Buffer(context, std::max<uint64_t>(valueBytes, 16), vk::BufferUse::Readback);
  }

  std::string name() const override { return "vulkan:" + context_.info().name; }

  void apply(std::vector<float>& rows) override {
    checkStencilRows(tableRows_, width_, rows.size());
    const size_t sourceFloats = size_t(sourceRows_) * width_;
    std::memcpy(values_.data(), rows.data(), sourceFloats * sizeof(float));
    context_.submitAndWait([&](VkCommandBuffer cmd) {
      timer_.reset(cmd);
      timer_.mark(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
      uint32_t first = 0;
      for (size_t b = 0; b < batchEnds_.size(); ++b) {
        gpu::LoopStencilPush push{first, batchEnds_[b] - first, sourceRows_, width_};
        if (push.stencilCount > 0) {
          if (b > 0) vk::computeToComputeBarrier(context_, cmd);
          pipeline_.dispatch(cmd, {&offsets_, &indices_, &weights_, &values_}, &push,
                             push.stencilCount);
        }
        first = batchEnds_[b];
      }
      timer_.mark(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
      vk::computeToHostBarrier(context_, cmd);
    });
    const auto intervals = timer_.intervalsNs();
    lastDeviceSeconds_ = intervals.empty() ? 0.0 : intervals[0] * 1e-9;
    std::memcpy(rows.data() + sourceFloats, static_cast<const float*>(values_.data()) + sourceFloats,
                (rows.size() - sourceFloats) * sizeof(float));
  }

  double lastDeviceSeconds() const override { return lastDeviceSeconds_; }

 private:
  vk::Context& context_;
  vk::ComputePipeline pipeline_;
  vk::GpuTimer timer_;
  size_t tableRows_;
  uint32_t sourceRows_;
  uint32_t width_;
  std::vector<uint32_t> batchEnds_;
  vk::Buffer offsets_, indices_, weights_, values_;
  double lastDeviceSeconds_ = 0.0;
};

}  // namespace

std::unique_ptr<StencilEvaluator> makeVulkanStencilEvaluator(vk::Context& context,
                                                             const FloatStencilTable& table,
                                                             uint32_t width) {
  return std::make_unique<VulkanStencilEvaluator>(context, table, width);
}

}  // namespace tessera
