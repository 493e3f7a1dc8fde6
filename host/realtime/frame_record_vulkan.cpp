// A real-time frame recorded into an engine's command buffer (frame_record_vulkan.h).
#include "realtime/frame_record_vulkan.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "common/stopwatch.h"
#include "realtime/detail/stitch_pattern_runner_vulkan.h"
#include "vk/context.h"
#include "vk/loader.h"

namespace tessera {
namespace {

void requireRange(const DeviceBufferRange& range, VkDeviceSize needed, const char* what) {
  if (!range.buffer)
    throw std::invalid_argument(std::string("RealtimeRecorder::record: no ") + what + " buffer");
  if (range.size < needed)
    throw std::length_error(std::string("RealtimeRecorder::record: the ") + what + " range has " +
                            std::to_string(range.size) + " bytes, the frame needs " +
                            std::to_string(needed));
}

// One barrier for the frame's writes: compute-shader writes (the pattern) and the transfer
// write (the draw command).
void frameBarrier(const vk::Context& context, VkCommandBuffer cmd, VkPipelineStageFlags srcStage,
                  VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = srcAccess;
  barrier.dstAccessMask = dstAccess;
  context.vk().vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 1, &barrier, 0, nullptr, 0,
                                    nullptr);
}

constexpr VkPipelineStageFlags kWriteStages =
    VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
constexpr VkAccessFlags kWriteAccess = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;

// Where the engine reads the results: drawing on a graphics queue, else (a compute-only
// queue) compute shaders and indirect commands.
VkPipelineStageFlags readStages(const vk::Context& context) {
  return context.queueSupportsGraphics()
             ? VK_PIPELINE_STAGE_VERTEX_INPUT_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT
             : VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT;
}

VkAccessFlags readAccess(const vk::Context& context) {
  return context.queueSupportsGraphics()
             ? VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_INDEX_READ_BIT |
                   VK_ACCESS_INDIRECT_COMMAND_READ_BIT
             : VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT;
}

}  // namespace

RealtimeRecorder::RealtimeRecorder(RealtimeTessellator& tessellator, uint32_t framesInFlight)
    : tessellator_(tessellator), framesInFlight_(framesInFlight) {
  if (framesInFlight < 1 || framesInFlight > 16)
    throw std::invalid_argument("RealtimeRecorder: framesInFlight must be in 1..16, got " +
                                std::to_string(framesInFlight));
}

RealtimeRecorder::~RealtimeRecorder() = default;

const RealtimeFrame& RealtimeRecorder::prepare(const Camera& camera) {
  prepared_ = true;
  return tessellator_.prepareFrame(camera);
}

VkDeviceSize RealtimeRecorder::vertexBytes(const RealtimeFrame& frame) {
  return VkDeviceSize(frame.vertexCount) * sizeof(gpu::GridVertex);
}

VkDeviceSize RealtimeRecorder::indexBytes(const RealtimeFrame& frame) {
  return VkDeviceSize(frame.triangles) * 3 * sizeof(uint32_t);
}

void RealtimeRecorder::record(VkCommandBuffer cmd, const RealtimeTargets& targets) {
  if (!prepared_)
    throw std::logic_error("RealtimeRecorder::record: no frame prepared (call prepare first)");
  RealtimeFrame& frame = tessellator_.frame_;
  const vk::Context& context = tessellator_.context_;
  const VkDeviceSize vertices = vertexBytes(frame), indices = indexBytes(frame);
  requireRange(targets.vertices, vertices, "vertex");
  requireRange(targets.indices, indices, "index");
  requireRange(targets.drawCommand, kDrawCommandBytes, "draw command");
  // The pattern binds the vertex and index ranges as storage buffers.
  const VkDeviceSize alignment = context.minStorageBufferOffsetAlignment();
  for (const auto& [range, what] :
       {std::pair(&targets.vertices, "vertex"), std::pair(&targets.indices, "index")})
    if (range->offset % alignment != 0)
      throw std::invalid_argument(std::string("RealtimeRecorder::record: the ") + what +
                                  " range's offset " + std::to_string(range->offset) +
                                  " is not a multiple of minStorageBufferOffsetAlignment (" +
                                  std::to_string(alignment) + ")");
  if (targets.drawCommand.offset % 4 != 0)
    throw std::invalid_argument("RealtimeRecorder::record: the draw command's offset " +
                                std::to_string(targets.drawCommand.offset) +
                                " is not a multiple of 4");
  const Stopwatch stopwatch;
  // Before writing: the previous use of these buffers (an earlier frame's draw reading them,
  // or its writes) is finished. Write-after-read and write-after-write in one barrier.
  frameBarrier(context, cmd, kWriteStages | readStages(context), kWriteAccess, kWriteStages,
               kWriteAccess);
  VkDrawIndexedIndirectCommand draw{uint32_t(3 * frame.triangles), 1, 0, 0, 0};
  context.vk().vkCmdUpdateBuffer(cmd, targets.drawCommand.buffer, targets.drawCommand.offset,
                                 sizeof draw, &draw);
  if (!frame.records.empty()) {
    tessellator_.runner_->record(cmd, size_t(recorded_ % framesInFlight_), frame.records,
                                 tessellator_.items_,
                                 {targets.vertices.buffer, targets.vertices.offset, vertices},
                                 {targets.indices.buffer, targets.indices.offset, indices});
    ++frame.dispatches;
  }
  // After: visible to the draw (or, on a compute-only queue, to compute and indirect reads).
  frameBarrier(context, cmd, kWriteStages, kWriteAccess, readStages(context), readAccess(context));
  ++recorded_;
  prepared_ = false;
  frame.patternSeconds = stopwatch.elapsedSeconds();
}

}  // namespace tessera
