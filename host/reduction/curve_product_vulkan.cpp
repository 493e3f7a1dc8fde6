// The Vulkan backend of CurveProduct: the band and the curves are packed in fp32
// (packCurves), written to mapped buffers, one dispatch of shaders/reduction_apply.comp.glsl
// computes every output point of every curve, and the results are unpacked in double.
#include <cstdint>  // before the generated SPIR-V array, which uses uint32_t

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "reduction/curve_product.h"
#include "reduction_apply_comp.h"
#include "shaders/layout.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"

namespace tessera {
namespace {

class VulkanCurveProduct final : public CurveProduct {
 public:
  explicit VulkanCurveProduct(vk::Context& context)
      : context_(context),
        pipeline_(context, {"reduction_apply.comp", kSpirv_reduction_apply_comp,
                            sizeof(kSpirv_reduction_apply_comp), 5, sizeof(gpu::BandApplyPush),
                            {}}) {}

  std::string name() const override { return "vulkan:" + context_.info().name; }

  std::vector<glm::dvec3> apply(const BandMatrix& m, const std::vector<glm::dvec3>& in,
                                int curves) override {
    const PackedCurves p = packCurves(m, in, curves);
    const uint64_t resultCount = uint64_t(p.curves) * p.rows;
    if (resultCount == 0) return {};
    const uint64_t limit = context_.info().maxStorageBufferRange;
    if (std::max<uint64_t>(resultCount, p.points.size()) * sizeof(glm::vec4) > limit ||
        resultCount > UINT32_MAX) {
      throw std::length_error("reduction row product: " + std::to_string(p.curves) +
                              " curves of " + std::to_string(std::max(p.rows, p.cols)) +
                              " points exceed the device's storage buffer range (" +
                              std::to_string(limit) + " bytes)");
    }
    fill(firsts_, p.firsts.data(), p.firsts.size() * sizeof(uint32_t), vk::BufferUse::Upload);
    fill(offsets_, p.offsets.data(), p.offsets.size() * sizeof(uint32_t), vk::BufferUse::Upload);
    fill(weights_, p.weights.data(), p.weights.size() * sizeof(float), vk::BufferUse::Upload);
    fill(points_, p.points.data(), p.points.size() * sizeof(glm::vec4), vk::BufferUse::Upload);
    fill(results_, nullptr, resultCount * sizeof(glm::vec4), vk::BufferUse::Readback);
    const gpu::BandApplyPush push{p.rows, p.cols, p.curves, 0u};
    context_.submitAndWait([&](VkCommandBuffer cmd) {
      pipeline_.dispatch(cmd, {&firsts_, &offsets_, &weights_, &points_, &results_}, &push,
                         static_cast<uint32_t>(resultCount));
      vk::computeToHostBarrier(context_, cmd);
    });
    std::vector<glm::vec4> results;
    results_.download(results, resultCount);
    return unpackCurves(p, results);
  }

 private:
  // Grows `buffer` to at least `bytes` (a zero-sized buffer is invalid: 16 at least) and
  // copies `data` in when given.
  void fill(vk::Buffer& buffer, const void* data, size_t bytes, vk::BufferUse use) {
    if (buffer.handle() == VK_NULL_HANDLE || buffer.size() < bytes) {
      buffer = vk::Buffer(context_, std::max<size_t>(bytes, 16), use);
    }
    if (data != nullptr && bytes > 0) buffer.upload(data, bytes);
  }

  vk::Context& context_;
  vk::ComputePipeline pipeline_;
  vk::Buffer firsts_, offsets_, weights_, points_, results_;
};

}  // namespace

std::unique_ptr<CurveProduct> makeVulkanCurveProduct(vk::Context& context) {
  return std::make_unique<VulkanCurveProduct>(context);
}

}  // namespace tessera
