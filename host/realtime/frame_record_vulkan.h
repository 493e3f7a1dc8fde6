// Engine interop for the real-time path (docs/realtime.md, "Recording a frame into an
// engine"): a frame's pattern is recorded into the engine's command buffer, and its vertices,
// indices and indexed-indirect draw command land in the engine's buffers, ready to draw with no
// readback. The context is usually made from the engine's device (vk::ExternalDevice).
//
// Per frame:
//   const RealtimeFrame& frame = recorder.prepare(camera);      // host only, submits nothing
//   ...grow the engine's buffers to RealtimeRecorder::vertexBytes(frame) / indexBytes(frame)...
//   recorder.record(cmd, targets);                              // records, submits nothing
//   ...engine: vkCmdDrawIndexedIndirect(cmd, targets.drawCommand...), submit with its fence...
// prepare() runs steps 1-2 of frame.h and the pattern's layout on the host, with nothing to
// wait for on the GPU (the counts never leave the host). Everything record() adds runs in the
// engine's submit.
#pragma once
#include "vk/backend_only.h"
#include <vulkan/vulkan.h>

#include <cstdint>

#include "realtime/frame.h"

namespace tessera {

// A range of an engine's buffer (on the context's device).
struct DeviceBufferRange {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceSize offset = 0;
  VkDeviceSize size = 0;
};

// Where record() writes. Usage flags the buffers need:
//   vertices: VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VERTEX_BUFFER_BIT; gpu::GridVertex, 32 bytes
//     each: position vec4 (w = 1) at offset 0, unit normal vec4 (w = 0) at offset 16;
//   indices: STORAGE_BUFFER_BIT | INDEX_BUFFER_BIT; uint32 triangle list, indices relative to
//     the range's first vertex (bind the vertex range at its offset);
//   drawCommand: TRANSFER_DST_BIT | INDIRECT_BUFFER_BIT; one VkDrawIndexedIndirectCommand
//     (20 bytes, offset a multiple of 4): {indexCount, 1, 0, 0, 0}.
// Offsets of vertices and indices: multiples of minStorageBufferOffsetAlignment.
struct RealtimeTargets {
  DeviceBufferRange vertices, indices, drawCommand;
};

class RealtimeRecorder {
 public:
  // `framesInFlight`: how many recorded frames may be pending on the GPU at once; the
  // recorder keeps that many slots of per-frame host data (patch records and work items).
  // The tessellator (and its context) must outlive the recorder.
  explicit RealtimeRecorder(RealtimeTessellator& tessellator, uint32_t framesInFlight = 2);
  ~RealtimeRecorder();
  RealtimeRecorder(const RealtimeRecorder&) = delete;
  RealtimeRecorder& operator=(const RealtimeRecorder&) = delete;

  // Culls, counts and lays the frame out on the host (submits nothing); the frame has its
  // counts and sizes but no vertices (vertices and indices stay null).
  const RealtimeFrame& prepare(const Camera& camera);

  // Records the prepared frame into `cmd` (recording, a primary or secondary command buffer
  // of the context's queue family, outside a render pass). Before the call, the GPU must be
  // done with the submit of the frame recorded framesInFlight calls ago (its fence signalled):
  // its slot's host data is overwritten now. Throws std::length_error naming the bytes needed
  // when a target is too small, std::invalid_argument for a missing buffer or bad offset.
  // The commands' synchronisation: docs/realtime.md.
  void record(VkCommandBuffer cmd, const RealtimeTargets& targets);

  static VkDeviceSize vertexBytes(const RealtimeFrame& frame);
  static VkDeviceSize indexBytes(const RealtimeFrame& frame);
  static constexpr VkDeviceSize kDrawCommandBytes = sizeof(VkDrawIndexedIndirectCommand);

 private:
  RealtimeTessellator& tessellator_;
  uint32_t framesInFlight_;
  uint64_t recorded_ = 0;  // frames recorded so far: the ring slot is recorded_ % framesInFlight_
  bool prepared_ = false;
};

}  // namespace tessera
