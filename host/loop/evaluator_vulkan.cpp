// The Vulkan backend of StencilEvaluator. A table whose arrays all fit one device array is
// uploaded once; each apply() writes the control rows into the mapped values buffer, runs one
// dispatch of shaders/loop_stencil.comp.glsl per batch (a compute-to-compute barrier between
// batches, as each level reads the one before) in one submission, and reads the rows back.
// A larger table goes in slices (loop/stencil_slices.h): per slice, the host gathers the rows it
// reads and its part of the table into fixed buffers, one dispatch runs, and its rows come
// back before the next slice, which may read them. The shader is the same in both modes.
#include <cstdint>  // before the generated SPIR-V array, which uses uint32_t

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "loop/evaluator.h"
#include "loop/stencil_slices.h"
#include "loop_stencil_comp.h"
#include "shaders/layout.h"
#include "tessera/errors.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"

namespace tessera {
namespace {

// A zero-sized buffer is invalid; an empty array still binds a small one.
vk::Buffer makeBuffer(vk::Context& context, uint64_t bytes, vk::BufferUse use) {
  return vk::Buffer(context, std::max<uint64_t>(bytes, 16), use);
}

vk::Buffer uploadArray(vk::Context& context, const void* data, size_t bytes) {
  vk::Buffer buffer = makeBuffer(context, bytes, vk::BufferUse::Upload);
  if (bytes) buffer.upload(data, bytes);
  return buffer;
}

// The bound on one device array: the caller's, within the device's binding and allocation
// limits (a device that does not report the latter is bound by the range alone).
uint64_t arrayLimit(const vk::DeviceInfo& info, uint64_t requested) {
  uint64_t limit = info.maxStorageBufferRange;
  if (info.maxMemoryAllocationSize > 0) limit = std::min(limit, info.maxMemoryAllocationSize);
  return requested > 0 ? std::min(limit, requested) : limit;
}

class VulkanStencilEvaluator final : public StencilEvaluator {
 public:
  VulkanStencilEvaluator(vk::Context& context, FloatStencilTable table, uint32_t width,
                         const VulkanStencilOptions& options)
      : context_(context),
        pipeline_(context, {"loop_stencil.comp", kSpirv_loop_stencil_comp,
                            sizeof(kSpirv_loop_stencil_comp), 4, sizeof(gpu::LoopStencilPush),
                            {}}),
        timer_(context, options.timeGpu ? 2 : 0),  // 0 marks: no query pool, marks no-ops
        tableRows_(table.rowCount()),
        sourceRows_(table.sourceRows),
        width_(width) {
    if (width == 0) throw std::invalid_argument("stencil evaluator: row width 0");
    const uint64_t limit = arrayLimit(context.info(), options.maxArrayBytes);
    const uint64_t valueBytes = uint64_t(table.rowCount()) * width * sizeof(float);
    const bool whole = valueBytes <= limit &&
                       uint64_t(table.offsets.size()) * sizeof(uint32_t) <= limit &&
                       uint64_t(table.indices.size()) * sizeof(uint32_t) <= limit &&
                       uint64_t(table.weights.size()) * sizeof(float) <= limit;
    if (whole) {
      batchEnds_ = table.batchEnds;
      offsets_ = uploadArray(context, table.offsets.data(), table.offsets.size() * sizeof(uint32_t));
      indices_ = uploadArray(context, table.indices.data(), table.indices.size() * sizeof(uint32_t));
      weights_ = uploadArray(context, table.weights.data(), table.weights.size() * sizeof(float));
      values_ = makeBuffer(context, valueBytes, vk::BufferUse::Readback);
      return;
    }
    sliced_ = true;
    slices_ = planStencilSlices(table, width, limit);
    uint64_t stencils = 0, entries = 0, rows = 0;
    for (const StencilSlice& s : slices_) {
      stencils = std::max<uint64_t>(stencils, s.stencilCount);
      entries = std::max<uint64_t>(entries, s.entryCount);
      rows = std::max<uint64_t>(rows, uint64_t(s.gatheredRows) + s.stencilCount);
    }
    offsets_ = makeBuffer(context, (stencils + 1) * sizeof(uint32_t), vk::BufferUse::Upload);
    indices_ = makeBuffer(context, entries * sizeof(uint32_t), vk::BufferUse::Upload);
    weights_ = makeBuffer(context, entries * sizeof(float), vk::BufferUse::Upload);
    values_ = makeBuffer(context, rows * width * sizeof(float), vk::BufferUse::Readback);
    table_ = std::move(table);  // read again at every apply()
  }

  std::string name() const override {
    const std::string device = "vulkan:" + context_.info().name;
    return sliced_ ? device + " in " + std::to_string(slices_.size()) + " batches" : device;
  }

  void apply(std::vector<float>& rows) override {
    checkStencilRows(tableRows_, width_, rows.size());
    if (sliced_)
      applySliced(rows);
    else
      applyWhole(rows);
  }

  double lastDeviceSeconds() const override { return lastDeviceSeconds_; }

 private:
  void applyWhole(std::vector<float>& rows) {
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
    lastDeviceSeconds_ = measuredSeconds();
    std::memcpy(rows.data() + sourceFloats, static_cast<const float*>(values_.data()) + sourceFloats,
                (rows.size() - sourceFloats) * sizeof(float));
  }

  void applySliced(std::vector<float>& rows) {
    std::vector<uint32_t> localRow(tableRows_, kLoopNone);
    lastDeviceSeconds_ = 0.0;
    for (const StencilSlice& slice : slices_) {
      gatherStencilSlice(table_, slice, rows.data(), width_, localRow, offsets_.as<uint32_t>(),
                         indices_.as<uint32_t>(), weights_.as<float>(), values_.as<float>());
      // The slice's rows follow its gathered rows, as the shader's row sourceRows + s.
      const gpu::LoopStencilPush push{0, slice.stencilCount, slice.gatheredRows, width_};
      context_.submitAndWait([&](VkCommandBuffer cmd) {
        timer_.reset(cmd);
        timer_.mark(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
        pipeline_.dispatch(cmd, {&offsets_, &indices_, &weights_, &values_}, &push,
                           push.stencilCount);
        timer_.mark(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
        vk::computeToHostBarrier(context_, cmd);
      });
      lastDeviceSeconds_ += measuredSeconds();
      std::memcpy(rows.data() + (size_t(sourceRows_) + slice.firstStencil) * width_,
                  values_.as<float>() + size_t(slice.gatheredRows) * width_,
                  size_t(slice.stencilCount) * width_ * sizeof(float));
    }
  }

  double measuredSeconds() const {
    const auto intervals = timer_.intervalsNs();
    return intervals.empty() ? 0.0 : intervals[0] * 1e-9;
  }

  vk::Context& context_;
  vk::ComputePipeline pipeline_;
  vk::GpuTimer timer_;
  size_t tableRows_;
  uint32_t sourceRows_;
  uint32_t width_;
  std::vector<uint32_t> batchEnds_;     // whole: the table's batches
  bool sliced_ = false;                 // a table past the array bound: in slices
  std::vector<StencilSlice> slices_;    // sliced: the plan (none for a table of no stencils)
  FloatStencilTable table_;             // sliced: the host copy the slices are gathered from
  vk::Buffer offsets_, indices_, weights_, values_;
  double lastDeviceSeconds_ = 0.0;
};

}  // namespace

std::unique_ptr<StencilEvaluator> makeVulkanStencilEvaluator(vk::Context& context,
                                                             FloatStencilTable table,
                                                             uint32_t width,
                                                             const VulkanStencilOptions& options) {
  return std::make_unique<VulkanStencilEvaluator>(context, std::move(table), width, options);
}

}  // namespace tessera
