// The stitched pattern's pipeline (shaders/stitch_pattern.comp.glsl) and its buffers, kept
// between frames: the scene's patches and edge points (uploaded once), and per frame the
// patch records and work items. Two ways to run it: run() submits and waits on the context's
// queue into its own mapped buffers (RealtimeTessellator::tessellate); record() records into an
// engine's command buffer, writing into the engine's buffer ranges (RealtimeRecorder).
#pragma once
#include "vk/backend_only.h"
#include <vector>

#include "shaders/layout.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"

namespace tessera {

class StitchPatternRunner {
 public:
  StitchPatternRunner(vk::Context& context, const std::vector<gpu::BicubicPatch>& patches,
                      const std::vector<gpu::vec4>& edgePoints);

  void run(const std::vector<gpu::StitchPatch>& records, const std::vector<uint32_t>& items,
           size_t vertexCount, size_t indexCount);
  const gpu::GridVertex* vertices() const { return vertices_.as<gpu::GridVertex>(); }
  const uint32_t* indices() const { return indices_.as<uint32_t>(); }

  // Records the dispatch into `cmd`, reading records and items from ring slot `slot` (host
  // memory written now: the GPU must be done with the slot's previous frame). Records no
  // barrier: the caller (RealtimeRecorder) brackets it.
  void record(VkCommandBuffer cmd, size_t slot, const std::vector<gpu::StitchPatch>& records,
              const std::vector<uint32_t>& items, const VkDescriptorBufferInfo& vertices,
              const VkDescriptorBufferInfo& indices);

 private:
  void checkRange(size_t vertexBytes, size_t indexBytes) const;

  struct RingSlot {
    vk::Buffer records, items;
  };
  vk::Context& context_;
  vk::ComputePipeline pipeline_;
  vk::Buffer patches_, edges_, records_, items_, vertices_, indices_;
  std::vector<RingSlot> ring_;
};

}  // namespace tessera
