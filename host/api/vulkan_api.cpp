// tessera/vulkan.h: a Tessellator and the real-time path on an engine's own device, through the
// context that borrows it (vk::ExternalDevice) and the frame recorder
// (realtime/frame_record_vulkan.h).
#include <tessera/vulkan.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "api/convert.h"
#include "api/public_errors.h"
#include "api/tessellator_access.h"
#include "realtime/frame.h"
#include "realtime/frame_record_vulkan.h"
#include "vk/context.h"

namespace tessera {

namespace {

vk::ExternalDevice borrowed(const VulkanDevice& d) {
  if (!d.instance || !d.physicalDevice || !d.device || !d.queue)
    throw ArgumentError("VulkanDevice: instance, physicalDevice, device and queue must be set");
  return {d.instance, d.physicalDevice, d.device, d.queueFamily, d.queue};
}

// The real-time path takes bicubic polynomial patches (its grids are evaluated as such).
std::vector<BezierPatch> bicubicPatches(const std::vector<Patch>& patches) {
  std::vector<BezierPatch> internal = api::toBezierPatches(patches);
  for (size_t k = 0; k < internal.size(); ++k) {
    if (internal[k].degreeU != 3 || internal[k].degreeV != 3)
      throw ArgumentError("RealtimeScene: patch " + std::to_string(k) + " is of degree " +
                          std::to_string(internal[k].degreeU) + "x" +
                          std::to_string(internal[k].degreeV) +
                          "; the real-time path takes bicubic patches only");
    std::vector<double>& weights = internal[k].weights;
    if (std::all_of(weights.begin(), weights.end(), [](double w) { return w == 1.0; }))
      weights.clear();  // weights all 1: the polynomial patch
    else
      throw ArgumentError("RealtimeScene: patch " + std::to_string(k) +
                          " is rational; the real-time path takes polynomial patches only");
  }
  return internal;
}

RealtimeOptions internalOptions(const RealtimeSceneOptions& o) {
  RealtimeOptions options;
  options.tolerancePixels = o.tolerancePixels;
  options.maxPerDirection = o.maxPerDirection;
  options.counts = o.provenCounts ? RealtimeCounts::Proven : RealtimeCounts::Estimated;
  options.hostThreads = o.hostThreads;
  return options;
}

}  // namespace

Tessellator tessellatorOnDevice(const VulkanDevice& device, const TessellatorOptions& options) {
  return TessellatorAccess::onDevice(borrowed(device), options);
}

struct RealtimeScene::Impl {
  // Destroyed in reverse: the recorder, the path's pipelines and buffers, then the context.
  std::unique_ptr<vk::Context> context;
  std::unique_ptr<RealtimeTessellator> tessellator;
  std::unique_ptr<RealtimeRecorder> recorder;
};

RealtimeScene::RealtimeScene(const VulkanDevice& device, const std::vector<Patch>& patches,
                             const RealtimeSceneOptions& options)
    : impl_(std::make_unique<Impl>()) {
  const vk::ExternalDevice external = borrowed(device);
  std::vector<BezierPatch> internal = bicubicPatches(patches);
  api::translatingErrors([&] {
    impl_->context = std::make_unique<vk::Context>(external);
    impl_->tessellator = std::make_unique<RealtimeTessellator>(*impl_->context, std::move(internal),
                                                               internalOptions(options));
    impl_->recorder =
        std::make_unique<RealtimeRecorder>(*impl_->tessellator, options.framesInFlight);
  });
}

RealtimeScene::~RealtimeScene() = default;
RealtimeScene::RealtimeScene(RealtimeScene&&) noexcept = default;
RealtimeScene& RealtimeScene::operator=(RealtimeScene&&) noexcept = default;

RealtimeFrameInfo RealtimeScene::prepare(const View& view) {
  Camera camera = api::toCamera(view);
  camera.nearW = api::nearPlaneW(camera.viewProjection, camera.nearW);
  return api::translatingErrors([&] {
    const RealtimeFrame& frame = impl_->recorder->prepare(camera);
    RealtimeFrameInfo info;
    info.vertexBytes = RealtimeRecorder::vertexBytes(frame);
    info.indexBytes = RealtimeRecorder::indexBytes(frame);
    info.triangles = frame.triangles;
    info.vertices = frame.vertexCount;
    info.visiblePatches = frame.records.size();
    info.culledPatches = frame.culled;
    info.capped = frame.capped;
    info.eyePlane = frame.fallback;
    return info;
  });
}

void RealtimeScene::record(VkCommandBuffer commandBuffer, const RealtimeFrameTargets& targets) {
  static_assert(kVertexBytes == sizeof(gpu::GridVertex), "the vertex layout the header states");
  static_assert(kDrawCommandBytes == RealtimeRecorder::kDrawCommandBytes, "one draw command");
  const auto range = [](const BufferRange& r) {
    return DeviceBufferRange{r.buffer, r.offset, r.size};
  };
  try {
    api::translatingErrors([&] {
      impl_->recorder->record(commandBuffer, {range(targets.vertices), range(targets.indices),
                                              range(targets.drawCommand)});
    });
  } catch (const std::logic_error& e) {  // a range too small, no frame prepared
    throw ArgumentError(e.what());
  }
}

}  // namespace tessera
