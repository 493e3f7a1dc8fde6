// Packing for the division-count shader, the fp32 mirror backend and the Vulkan backend
// (one dispatch of shaders/division_count.comp.glsl, one invocation per patch).
#include <cstdint>  // before the generated SPIR-V array, which uses uint32_t

#include "division_gpu.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "division_count_comp.h"
#include "mirror/division_mirror.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"

namespace tessera {

DivisionBatch packDivisionBatch(const std::vector<RationalBezierPatch>& patches) {
  DivisionBatch batch;
  batch.patches.reserve(patches.size());
  for (size_t p = 0; p < patches.size(); ++p) {
    try {
      validateDivisionInput(patches[p], DivisionMethod::Split);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("patch " + std::to_string(p) + ": " + e.what());
    }
    batch.patches.push_back({static_cast<uint32_t>(batch.points.size()),
                             static_cast<uint32_t>(patches[p].degreeU),
                             static_cast<uint32_t>(patches[p].degreeV), 0u});
    for (const glm::dvec4& h : patches[p].cpw) batch.points.push_back(gpu::vec4(h));
  }
  return batch;
}

gpu::DivisionPush divisionPush(const DivisionOptions& options, size_t patchCount) {
  if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance))
    throw std::invalid_argument("division count: the tolerance must be a finite number > 0");
  if (options.maxPerDirection < 1 || options.ratioPieces < 1 || options.ratioPieces > 64)
    throw std::invalid_argument("division count: need maxPerDirection ≥ 1 and 1 ≤ q ≤ 64");
  if (options.zeroClassThreshold != 0.0 || options.method != DivisionMethod::Split)
    throw std::invalid_argument("division count: the GPU runs the split method, exact zeros only");
  return {static_cast<float>(options.tolerance), static_cast<uint32_t>(options.maxPerDirection),
          static_cast<uint32_t>(options.ratioPieces), static_cast<uint32_t>(patchCount)};
}

namespace {

class MirrorDivisionCounter final : public DivisionCounter {
 public:
  std::vector<gpu::DivisionResult> count(const DivisionBatch& batch,
                                         const DivisionOptions& options) override {
    const gpu::DivisionPush push = divisionPush(options, batch.patches.size());
    std::vector<gpu::DivisionResult> out(batch.patches.size());
    for (size_t p = 0; p < out.size(); ++p)
      out[p] = mirror::divisionCounts(batch.patches[p],
                                      batch.points.data() + batch.patches[p].firstPoint, push);
    return out;
  }
};

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
    if (buffer.handle() != VK_NULL_HANDLE && buffer.size() >= bytes) return;
    const uint64_t limit = context_.info().maxStorageBufferRange;
    if (bytes > limit)
      throw std::length_error("division counts: " + std::to_string(bytes) +
                              " bytes exceed the device's storage buffer range (" +
                              std::to_string(limit) + " bytes); split the batch");
    buffer = vk::Buffer(context_, std::max<size_t>(bytes, 16), use);
  }

  vk::Context& context_;
  vk::ComputePipeline pipeline_;
  vk::Buffer patches_, points_, results_;
};

}  // namespace

std::unique_ptr<DivisionCounter> makeMirrorDivisionCounter() {
  return std::make_unique<MirrorDivisionCounter>();
}

std::unique_ptr<DivisionCounter> makeVulkanDivisionCounter(vk::Context& context) {
  return std::make_unique<VulkanDivisionCounter>(context);
}

}  // namespace tessera
