// The Vulkan backend of TrimClassifier: one dispatch of shaders/trim_classify.comp.glsl, one
// invocation per node.
#include <cstdint>  // before the generated SPIR-V array, which uses uint32_t

#include "trim/trim_classifier.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "trim_classify_comp.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"

namespace tessera {
namespace {

class VulkanTrimClassifier final : public TrimClassifier {
 public:
  explicit VulkanTrimClassifier(vk::Context& context)
      : context_(context),
        pipeline_(context, {"trim_classify.comp", kSpirv_trim_classify_comp,
                            sizeof(kSpirv_trim_classify_comp), 5, sizeof(gpu::TrimPush), {}}) {}

  std::string name() const override { return "vulkan: " + context_.info().name; }

  std::vector<uint32_t> classify(const TrimSet& set,
                                 const std::vector<gpu::TrimQuery>& queries) override {
    validateTrimQueries(set, queries);
    std::vector<uint32_t> out;
    if (queries.empty()) return out;
    if (queries.size() > UINT32_MAX)
      throw std::length_error("trim classification: more than 2³² − 1 nodes in one call");
    const gpu::TrimPush push{uint32_t(queries.size()), 0u, 0u, 0u};
    // Buffers only grow, so the frontier's levels and repeated batches reuse them.
    upload(faces_, set.faces.data(), set.faces.size() * sizeof(gpu::TrimFace));
    upload(pieces_, set.pieces.data(), set.pieces.size() * sizeof(gpu::TrimPiece));
    upload(segments_, set.segments.data(), set.segments.size() * sizeof(gpu::vec4));
    upload(queries_, queries.data(), queries.size() * sizeof(gpu::TrimQuery));
    ensure(results_, queries.size() * sizeof(uint32_t), vk::BufferUse::Readback);
    context_.submitAndWait([&](VkCommandBuffer cmd) {
      pipeline_.dispatch(cmd, {&faces_, &pieces_, &segments_, &queries_, &results_}, &push,
                         push.queryCount);
      vk::computeToHostBarrier(context_, cmd);
    });
    results_.download(out, queries.size());
    return out;
  }

 private:
  void ensure(vk::Buffer& buffer, size_t bytes, vk::BufferUse use) {
    vk::requireStorageRange(context_, bytes, "trim classification");
    vk::ensureCapacity(context_, buffer, std::max<size_t>(bytes, 16), use);
  }

  void upload(vk::Buffer& buffer, const void* data, size_t bytes) {
    ensure(buffer, bytes, vk::BufferUse::Upload);
    if (bytes > 0) buffer.upload(data, bytes);
  }

  vk::Context& context_;
  vk::ComputePipeline pipeline_;
  vk::Buffer faces_, pieces_, segments_, queries_, results_;
};

}  // namespace

std::unique_ptr<TrimClassifier> makeVulkanTrimClassifier(vk::Context& context) {
  return std::make_unique<VulkanTrimClassifier>(context);
}

}  // namespace tessera
