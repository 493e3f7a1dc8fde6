// The stitched pattern's pipeline, run or recorded (detail/stitch_pattern_runner_vulkan.h).
#include <cstdint>  // before the generated SPIR-V array, which uses uint32_t

#include "realtime/detail/stitch_pattern_runner_vulkan.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "eval/evaluator.h"
#include "stitch_pattern_comp.h"

namespace tessera {

StitchPatternRunner::StitchPatternRunner(vk::Context& context,
                                         const std::vector<gpu::BicubicPatch>& patches,
                                         const std::vector<gpu::vec4>& edgePoints)
    : context_(context),
      pipeline_(context, {"stitch_pattern.comp",
                          kSpirv_stitch_pattern_comp,
                          sizeof(kSpirv_stitch_pattern_comp),
                          6,
                          sizeof(gpu::StitchPush),
                          {}}) {
  vk::ensureCapacity(context_, patches_,
                     std::max<size_t>(1, patches.size()) * sizeof(gpu::BicubicPatch),
                     vk::BufferUse::Upload);
  vk::ensureCapacity(context_, edges_, std::max<size_t>(1, edgePoints.size()) * sizeof(gpu::vec4),
                     vk::BufferUse::Upload);
  if (!patches.empty()) patches_.upload(patches);
  if (!edgePoints.empty()) edges_.upload(edgePoints);
}

void StitchPatternRunner::checkRange(size_t vertexBytes, size_t indexBytes) const {
  vk::requireStorageRange(context_, vertexBytes, "real-time pattern (vertices)");
  vk::requireStorageRange(context_, indexBytes, "real-time pattern (indices)");
}

void StitchPatternRunner::run(const std::vector<gpu::StitchPatch>& records,
                              const std::vector<uint32_t>& items, size_t vertexCount,
                              size_t indexCount) {
  const size_t vertexBytes = vertexCount * sizeof(gpu::GridVertex);
  checkRange(vertexBytes, indexCount * sizeof(uint32_t));
  vk::ensureCapacity(context_, records_, records.size() * sizeof(gpu::StitchPatch),
                     vk::BufferUse::Upload);
  vk::ensureCapacity(context_, items_, items.size() * sizeof(uint32_t), vk::BufferUse::Upload);
  vk::ensureCapacity(context_, vertices_, vertexBytes, vk::BufferUse::Readback);
  vk::ensureCapacity(context_, indices_, indexCount * sizeof(uint32_t), vk::BufferUse::Readback);
  records_.upload(records);
  items_.upload(items);
  gpu::StitchPush push{uint32_t(items.size()), kDegenerateEpsFp32, 0, 0};
  context_.submitAndWait([&](VkCommandBuffer cmd) {
    pipeline_.dispatch(cmd, {&patches_, &records_, &edges_, &items_, &vertices_, &indices_}, &push,
                       push.itemCount);
    vk::computeToHostBarrier(context_, cmd);
  });
}

void StitchPatternRunner::record(VkCommandBuffer cmd, size_t slot,
                                 const std::vector<gpu::StitchPatch>& records,
                                 const std::vector<uint32_t>& items,
                                 const VkDescriptorBufferInfo& vertices,
                                 const VkDescriptorBufferInfo& indices) {
  checkRange(size_t(vertices.range), size_t(indices.range));
  if (ring_.size() <= slot) ring_.resize(slot + 1);
  RingSlot& ring = ring_[slot];
  vk::ensureCapacity(context_, ring.records, records.size() * sizeof(gpu::StitchPatch),
                     vk::BufferUse::Upload);
  vk::ensureCapacity(context_, ring.items, items.size() * sizeof(uint32_t), vk::BufferUse::Upload);
  // Host-coherent memory written before vkQueueSubmit is visible to the GPU (the submit's
  // implicit host-write dependency): the shader reads the ring directly, no copy.
  ring.records.upload(records);
  ring.items.upload(items);
  gpu::StitchPush push{uint32_t(items.size()), kDegenerateEpsFp32, 0, 0};
  pipeline_.dispatch(cmd,
                     {{patches_.handle(), 0, VK_WHOLE_SIZE},
                      {ring.records.handle(), 0, VK_WHOLE_SIZE},
                      {edges_.handle(), 0, VK_WHOLE_SIZE},
                      {ring.items.handle(), 0, VK_WHOLE_SIZE},
                      vertices,
                      indices},
                     &push, push.itemCount);
}

}  // namespace tessera
