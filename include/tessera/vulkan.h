// Engines with their own Vulkan device (docs/api.md, "Engines with their own Vulkan device"):
// Tessera borrows the engine's instance, device and queue instead of making its own, for the
// Tessellator's calls and for the real-time path, whose frames are recorded into the engine's
// command buffers and land in the engine's buffers, ready to draw with no readback.
//
// Per frame of a RealtimeScene:
//   const RealtimeFrameInfo info = scene.prepare(view);        // host only, submits nothing
//   ...the engine sizes its buffers: info.vertexBytes, info.indexBytes...
//   scene.record(commandBuffer, targets);                      // records, submits nothing
//   ...engine: vkCmdDrawIndexedIndirect(.., targets.drawCommand.buffer, offset, 1, 0), submit...
//
// This header includes <vulkan/vulkan.h> for its types only: Tessera calls Vulkan through its
// own loader, so an engine may use the loader's prototypes, volk or VK_NO_PROTOTYPES.
#pragma once
#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "tessera/tessera.h"

namespace tessera {

// The engine's objects, lent: `device` made from `physicalDevice` of `instance` with Vulkan 1.1
// or later and VK_KHR_push_descriptor enabled; `queue` a queue of `queueFamily`, which must
// support compute. Tessera never destroys them (they must outlive what borrows them) and
// submits to `queue` only inside its own calls (Tessellator's; RealtimeScene::record submits
// nothing): the engine must not use the queue from another thread meanwhile. A device that
// lacks something is a DeviceError naming it.
struct VulkanDevice {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  uint32_t queueFamily = 0;
  VkQueue queue = VK_NULL_HANDLE;
};

// A Tessellator on the engine's device: every Tessellator call, meshes returned to the host as
// on its own device. options.device must be Auto (a device failure during a call moves to the
// CPU, as always) or Vulkan (it throws DeviceError instead); Cpu and a deviceName are
// ArgumentError. options.threads applies.
Tessellator tessellatorOnDevice(const VulkanDevice& device, const TessellatorOptions& options = {});

// The real-time path (docs/realtime.md): every frame re-tessellates the whole scene of bicubic
// patches for one view, each patch to a grid and its sides to shared counts in pixels, so the
// mesh is watertight (shared vertices equal bit for bit) and no triangle is more than about
// tolerancePixels off the surface on screen.
struct RealtimeSceneOptions {
  double tolerancePixels = 1.0;
  int maxPerDirection = 64;     // counts above are clamped (RealtimeFrameInfo::capped)
  bool provenCounts = false;    // true: counts from a proven bound (about twice the triangles);
                                // false: a measured estimate (docs/realtime.md, "Counts")
  uint32_t framesInFlight = 2;  // recorded frames that may be pending on the GPU at once, 1..16
  unsigned hostThreads = 0;     // threads for the host's part of prepare(); 0: all cores
};

// A range of one of the engine's buffers (on the lent device).
struct BufferRange {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceSize offset = 0;
  VkDeviceSize size = 0;
};

// Where record() writes. Usage flags the buffers need:
//   vertices: STORAGE_BUFFER | VERTEX_BUFFER; kVertexBytes each: position (4 floats, w = 1) at
//     offset 0, unit normal (4 floats, w = 0) at offset 16;
//   indices: STORAGE_BUFFER | INDEX_BUFFER; uint32 triangle list, counter-clockwise seen from
//     the side the normals point to, relative to the range's first vertex (bind the vertex
//     range at its offset);
//   drawCommand: TRANSFER_DST | INDIRECT_BUFFER; one VkDrawIndexedIndirectCommand
//     {indexCount, 1, 0, 0, 0} (offset a multiple of 4).
// The offsets of vertices and indices: multiples of the device's minStorageBufferOffsetAlignment.
struct RealtimeFrameTargets {
  BufferRange vertices, indices, drawCommand;
};

// What prepare() found: the sizes record() needs and the frame's counts.
struct RealtimeFrameInfo {
  VkDeviceSize vertexBytes = 0, indexBytes = 0;
  size_t triangles = 0, vertices = 0;
  size_t visiblePatches = 0, culledPatches = 0;
  size_t capped = 0;    // patches and sides whose count hit maxPerDirection
  size_t eyePlane = 0;  // patches and sides whose net reaches the eye plane (counted by view)
};

// Owns the path's pipelines and scene buffers on the lent device (made once; destroying the
// scene leaves the device alive and does not wait for it: the engine waits for its frames
// first). Not for use by two threads at once.
class RealtimeScene {
 public:
  static constexpr VkDeviceSize kVertexBytes = 32;
  static constexpr VkDeviceSize kDrawCommandBytes = sizeof(VkDrawIndexedIndirectCommand);

  // Throws ArgumentError for a patch that is not bicubic and polynomial (weights all 1), or a
  // bad option; DeviceError for a device that lacks what the path needs.
  RealtimeScene(const VulkanDevice& device, const std::vector<Patch>& patches,
                const RealtimeSceneOptions& options = {});
  ~RealtimeScene();
  RealtimeScene(RealtimeScene&&) noexcept;
  RealtimeScene& operator=(RealtimeScene&&) noexcept;
  RealtimeScene(const RealtimeScene&) = delete;
  RealtimeScene& operator=(const RealtimeScene&) = delete;

  // Culls, counts and lays the frame out for `view` on the host; submits nothing. The near
  // plane (where counting in pixels stops) is read from the view's matrix when it is a
  // perspective one (lookAtView's), else taken at w = 0.01.
  RealtimeFrameInfo prepare(const View& view);

  // Records the prepared frame into `commandBuffer` (recording; primary or secondary, of the
  // queue family lent; outside a render pass). Before the call, the GPU must be done with the
  // frame recorded framesInFlight calls ago (its fence signalled). The commands end with the
  // writes made available to vertex input, index reads and the indirect draw
  // (docs/realtime.md, "Recording a frame into an engine"). Throws ArgumentError for a frame not
  // prepared, a missing buffer, a misaligned offset or a range too small (naming the bytes).
  void record(VkCommandBuffer commandBuffer, const RealtimeFrameTargets& targets);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tessera
