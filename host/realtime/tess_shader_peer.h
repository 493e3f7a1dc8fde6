// The fixed-function alternative to Tessera's view-dependent tessellation (bench case 6):
// bicubic patches drawn through Vulkan's tessellation stages (shaders/tess_peer.*.glsl), with
// per-edge factors from a screen-space chord-error rule (tolerance in pixels, factor ≤ 64),
// into an offscreen colour + depth target. The rule as derived overshoots the tolerance (it
// ignores the twist, and a pole's side gets factor 1); its two tuning knobs are options. Needs the tessellationShader feature; counts the
// triangles the tessellator made with a pipeline-statistics query when the device has one.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <vector>

#include "shaders/layout.h"

namespace tessera {
namespace vk {
class Context;
}

struct TessPeerOptions {
  uint32_t width = 1920, height = 1080;
  float tolerancePixels = 1.0f;
  float maxFactor = 64.0f;  // what every device supports is at least 64
  // Multiplies every factor before it is rounded up (as engines tune a screen-space factor
  // heuristic): 1 is the chord rule as derived.
  float factorScale = 1.0f;
  // A collapsed side (four equal control points: a pole) takes this multiple of the inner
  // factor along it (at most maxFactor); 0: its own factor, 1. No crack either way: no other
  // patch shares that side.
  float collapsedSideScale = 0.0f;
};

class TessShaderPeer {
 public:
  // Throws VulkanUnavailable when the device has no tessellation shaders or cannot draw.
  TessShaderPeer(vk::Context& context, const std::vector<gpu::BicubicPatch>& patches,
                 const TessPeerOptions& options = {});
  ~TessShaderPeer();
  TessShaderPeer(const TessShaderPeer&) = delete;
  TessShaderPeer& operator=(const TessShaderPeer&) = delete;

  // Draws one frame seen through `viewProjection` (Vulkan clip space) and waits for it.
  // Returns the primitives that reached the clipper (the tessellated triangles of the
  // patches not culled), or 0 when the device has no pipeline-statistics queries.
  uint64_t drawFrame(const glm::mat4& viewProjection);
  bool countsTriangles() const;
  // The next frames' factor scale (TessPeerOptions::factorScale), for searching it.
  void setFactorScale(float factorScale);

  // Draws one frame as drawFrame does, through a pipeline with a geometry stage that records
  // every triangle the tessellator made (before clipping): world corners, their (u, v) and
  // the patch. For measuring the peer's screen error; needs the geometryShader and
  // vertexPipelineStoresAndAtomics features (capturesTriangles()), else throws
  // VulkanUnavailable. Not for timing: the extra stage and writes cost.
  std::vector<gpu::TessPeerTriangle> captureFrame(const glm::mat4& viewProjection);
  bool capturesTriangles() const;

  struct Objects;  // the Vulkan objects, defined in the .cpp

 private:
  std::unique_ptr<Objects> d_;
};

}  // namespace tessera
