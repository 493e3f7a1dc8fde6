// Where the viewer's frames come from: the seam between the viewer and the tessellator.
//
// Today a frame is made by the real-time path (host/realtime/frame.h): the tessellator fills
// its own mapped buffers, and writeDrawVertices un-indexes them on the host into the viewer's
// vertex buffer (each triangle gets its corner numbers for the wireframe and its palette
// value). Once the engine-interop context lands (issue 16, "Engine interop"), this class is
// the one place to change: the tessellation would be recorded into the viewer's command
// buffer and write the draw buffers on the GPU, with no host round trip.
#pragma once
#include "vk/backend_only.h"
#include <cstdint>
#include <memory>
#include <vector>

#include "mesh/mesh.h"
#include "realtime/frame.h"
#include "vk/buffer.h"
#include "vk/context.h"

namespace tessera::viewer {

enum class Colouring { Shaded, Patch, Depth };  // Depth: the patch's level, ⌈log2 max(N_u, N_v)⌉

class FrameSource {
 public:
  // Throws std::invalid_argument as RealtimeTessellator does (a patch that is not bicubic
  // and polynomial, a bad tolerance).
  FrameSource(vk::Context& context, std::vector<BezierPatch> patches, double tolerancePixels);

  // A new tessellation for `camera` (the last one is dropped).
  const RealtimeFrame& tessellate(const Camera& camera);
  // Makes the tessellator again for another tolerance; the next tessellate() uses it.
  void setTolerance(double pixels);
  double tolerance() const { return tolerance_; }

  // The last frame's triangles, un-indexed, into `out` (made larger when needed, as a vertex
  // buffer); returns the vertex count. The GPU must be done with `out`.
  uint32_t writeDrawVertices(Colouring colouring, vk::Buffer& out) const;
  // The last frame's mesh as drawn: the GPU's vertices and indices (each patch's own copy of
  // its border vertices: equal bit for bit to its neighbour's), normals, and patch ids.
  TriangleMesh lastMesh() const;
  // The last frame's screen-space error (host/realtime/frame.h) for `camera`: with the
  // tessellation frozen, for a camera it was not made for.
  ScreenErrorReport measureError(const Camera& camera) const;

  const RealtimeFrame* lastFrame() const { return frame_; }
  const std::vector<BezierPatch>& patches() const { return tessellator_->patches(); }

 private:
  vk::Context& context_;
  double tolerance_;
  std::unique_ptr<RealtimeTessellator> tessellator_;
  const RealtimeFrame* frame_ = nullptr;
};

}  // namespace tessera::viewer
