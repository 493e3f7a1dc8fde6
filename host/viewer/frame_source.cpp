#include "viewer/frame_source.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "viewer/draw_vertex.h"

namespace tessera::viewer {
namespace {

// The first triangle of each record and, at the end, the frame's triangle count: record r
// owns triangles [starts[r], starts[r + 1]) (records are laid out in order, frame_vulkan.cpp).
std::vector<size_t> triangleStarts(const RealtimeFrame& frame) {
  std::vector<size_t> starts;
  for (const gpu::StitchPatch& r : frame.records) starts.push_back(r.firstIndex / 3);
  starts.push_back(frame.triangles);
  if (!std::is_sorted(starts.begin(), starts.end()))
    throw std::logic_error("viewer: the frame's patch records are not in triangle order");
  return starts;
}

float paletteValue(const gpu::StitchPatch& r, Colouring colouring) {
  if (colouring == Colouring::Patch) return float(r.patchIndex);
  if (colouring == Colouring::Depth)
    return float(std::ceil(std::log2(double(std::max(r.nu, r.nv)))));
  return 0.0f;
}

}  // namespace

FrameSource::FrameSource(vk::Context& context, std::vector<BezierPatch> patches,
                         double tolerancePixels)
    : context_(context), tolerance_(tolerancePixels) {
  RealtimeOptions options;
  options.tolerancePixels = tolerancePixels;
  tessellator_ = std::make_unique<RealtimeTessellator>(context, std::move(patches), options);
}

const RealtimeFrame& FrameSource::tessellate(const Camera& camera) {
  frame_ = &tessellator_->tessellate(camera);
  return *frame_;
}

void FrameSource::setTolerance(double pixels) {
  RealtimeOptions options;
  options.tolerancePixels = pixels;
  auto next = std::make_unique<RealtimeTessellator>(context_, tessellator_->patches(), options);
  tessellator_ = std::move(next);
  tolerance_ = pixels;
  frame_ = nullptr;
}

uint32_t FrameSource::writeDrawVertices(Colouring colouring, vk::Buffer& out) const {
  if (!frame_ || frame_->triangles == 0) return 0;
  const RealtimeFrame& f = *frame_;
  const size_t count = 3 * f.triangles;
  if (out.size() < count * sizeof(DrawVertex))
    out = vk::Buffer(context_, VkDeviceSize(count + count / 4) * sizeof(DrawVertex),
                     vk::BufferUse::Upload, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  DrawVertex* target = out.as<DrawVertex>();
  const std::vector<size_t> starts = triangleStarts(f);
  for (size_t r = 0; r < f.records.size(); ++r) {
    const float value = paletteValue(f.records[r], colouring);
    for (size_t t = starts[r]; t < starts[r + 1]; ++t)
      for (int k = 0; k < 3; ++k) {
        const gpu::GridVertex& v = f.vertices[f.indices[3 * t + k]];
        target[3 * t + k] = {glm::vec3(v.position.x, v.position.y, v.position.z), value,
                             glm::vec3(v.normal.x, v.normal.y, v.normal.z), float(k)};
      }
  }
  return uint32_t(count);
}

TriangleMesh FrameSource::lastMesh() const {
  TriangleMesh mesh;
  if (!frame_) return mesh;
  const RealtimeFrame& f = *frame_;
  mesh.positions.reserve(f.vertexCount);
  mesh.normals.reserve(f.vertexCount);
  for (size_t i = 0; i < f.vertexCount; ++i) {
    const gpu::GridVertex& v = f.vertices[i];
    mesh.positions.emplace_back(v.position.x, v.position.y, v.position.z);
    mesh.normals.emplace_back(v.normal.x, v.normal.y, v.normal.z);
  }
  mesh.indices.assign(f.indices, f.indices + 3 * f.triangles);
  // A record's vertices run from its firstVertex to the next record's.
  mesh.patchIds.assign(f.vertexCount, 0u);
  for (size_t r = 0; r < f.records.size(); ++r) {
    const size_t end = r + 1 < f.records.size() ? f.records[r + 1].firstVertex : f.vertexCount;
    std::fill(mesh.patchIds.begin() + f.records[r].firstVertex, mesh.patchIds.begin() + end,
              f.records[r].patchIndex);
  }
  return mesh;
}

ScreenErrorReport FrameSource::measureError(const Camera& camera) const {
  if (!frame_) return {};
  return measureScreenError(*frame_, tessellator_->patches(), camera);
}

}  // namespace tessera::viewer
