// The Vulkan backend of TrimClassifier: one dispatch of shaders/trim_classify.comp.glsl, one
// invocation per node. The set (faces, pieces, segments, bins) is uploaded once per beginSet,
// so the trimmed quad-tree's levels upload only their nodes.
#include <cstdint>  // before the generated SPIR-V array, which uses uint32_t

#include "trim/trim_classifier.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "trim_classify_comp.h"
#include "vk/async_submission.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"

namespace tessera {
namespace {

class VulkanTrimClassifier final : public TrimClassifier {
 public:
  explicit VulkanTrimClassifier(vk::Context& context)
      : context_(context),
        pipeline_(context, {"trim_classify.comp", kSpirv_trim_classify_comp,
                            sizeof(kSpirv_trim_classify_comp), 6, sizeof(gpu::TrimPush), {}}) {}

  std::string name() const override { return "vulkan: " + context_.info().name; }

  std::vector<uint32_t> classify(const TrimSet& set,
                                 const std::vector<gpu::TrimQuery>& queries) override {
    std::vector<uint32_t> out;
    boundSet_ = nullptr;  // a plain call uploads its set, whichever it is
    if (!prepare(set, queries)) return out;
    context_.submitAndWait([&](VkCommandBuffer cmd) { record(cmd); });
    results_.download(out, queries.size());
    return out;
  }

  // The same dispatch, submitted without waiting: the trimmed quad-tree's level classification,
  // submitted next, runs after it on the queue, and its wait covers both.
  void startClassify(const TrimSet& set, const std::vector<gpu::TrimQuery>& queries) override {
    startedCount_ = 0;
    if (!prepare(set, queries)) return;
    submission_.submit([&](VkCommandBuffer cmd) { record(cmd); });
    startedCount_ = queries.size();
  }

  std::vector<uint32_t> finishClassify() override {
    std::vector<uint32_t> out;
    if (startedCount_ == 0) return out;
    submission_.wait();
    results_.download(out, startedCount_);
    startedCount_ = 0;
    return out;
  }

  void beginSet(const TrimSet& set) override {
    submission_.wait();  // a started dispatch reads the buffers this overwrites
    startedCount_ = 0;
    uploadSet(set);
    boundSet_ = &set;
  }

 private:
  // Uploads the queries, and the set unless beginSet bound it, for record(); false when there
  // is nothing to classify. Waits first for a started dispatch, which reads these buffers.
  bool prepare(const TrimSet& set, const std::vector<gpu::TrimQuery>& queries) {
    validateTrimQueries(set, queries);
    submission_.wait();
    startedCount_ = 0;
    if (queries.empty()) return false;
    if (queries.size() > UINT32_MAX)
      throw std::length_error("trim classification: more than 2³² − 1 nodes in one call");
    push_ = {uint32_t(queries.size()), 0u, 0u, 0u};
    if (&set != boundSet_) uploadSet(set);
    upload(queries_, queries.data(), queries.size() * sizeof(gpu::TrimQuery));
    ensure(results_, queries.size() * sizeof(uint32_t), vk::BufferUse::Readback);
    return true;
  }

  // Buffers only grow, so the sets of several trees and repeated batches reuse them.
  void uploadSet(const TrimSet& set) {
    upload(faces_, set.faces.data(), set.faces.size() * sizeof(gpu::TrimFace));
    upload(pieces_, set.pieces.data(), set.pieces.size() * sizeof(gpu::TrimPiece));
    upload(segments_, set.segments.data(), set.segments.size() * sizeof(gpu::vec4));
    upload(binWords_, set.binWords.data(), set.binWords.size() * sizeof(uint32_t));
  }

  void record(VkCommandBuffer cmd) {
    pipeline_.dispatch(cmd, {&faces_, &pieces_, &segments_, &binWords_, &queries_, &results_},
                       &push_, push_.queryCount);
    vk::computeToHostBarrier(context_, cmd);
  }

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
  vk::Buffer faces_, pieces_, segments_, binWords_, queries_, results_;
  gpu::TrimPush push_{};
  const TrimSet* boundSet_ = nullptr;         // the set of the last beginSet, uploaded
  vk::AsyncSubmission submission_{context_};  // declared last: destroyed (waited for) first
  size_t startedCount_ = 0;                   // queries of the started dispatch
};

}  // namespace

std::unique_ptr<TrimClassifier> makeVulkanTrimClassifier(vk::Context& context) {
  return std::make_unique<VulkanTrimClassifier>(context);
}

}  // namespace tessera
