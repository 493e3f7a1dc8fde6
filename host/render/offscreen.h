// Offscreen pictures of a triangle mesh through a Vulkan graphics pipeline (shaders/mesh.*.glsl):
// no window, no swapchain; the colour image is copied to a host-visible buffer and returned
// as RGBA8 pixels, top row first, ready for host/io/png_writer.h.
//
// How per-triangle values reach the shader: the mesh is un-indexed (three vertices of its own
// per triangle) and each vertex carries its triangle's value next to the position, passed on
// as a flat varying. Un-indexing is needed anyway for the wireframe, whose barycentric
// coordinates come from the corner number each vertex carries.
#pragma once
#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "mesh/mesh.h"
#include "mesh/tessellate.h"

namespace tessera {
namespace vk {
class Context;
}

struct BoundingBox {
  glm::vec3 lo{std::numeric_limits<float>::max()};
  glm::vec3 hi{std::numeric_limits<float>::lowest()};
  bool empty() const { return lo.x > hi.x; }
  void add(const glm::vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void add(const BoundingBox& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
};

// The box of the positions that triangles use (unused vertices do not widen the frame).
BoundingBox boundingBox(const TriangleMesh& mesh);

// The clear colour: a pixel no triangle covers has exactly these bytes.
constexpr std::array<uint8_t, 4> kRenderBackground = {244, 245, 247, 255};

// Largest width or height: 4096 is what every Vulkan device must support for a framebuffer.
constexpr int kMaxRenderExtent = 4096;

struct RenderOptions {
  int width = 1024, height = 768;
  enum class Colour {
    Shaded,  // one porcelain colour; the values are ignored
    Depth,   // palette by quad-tree level (the values); level 10 and deeper share a colour
    Patch,   // palette by patch id (the values), ten colours in turn
  };
  Colour colour = Colour::Shaded;
  bool wireframe = false;
  float wireWidth = 1.0f;  // pixels
  // The direction the camera looks in, and the world direction that is up in the picture.
  // The default looks at the Utah teapot (z up, spout towards +x) from the front right and
  // a little above, a three-quarter view showing the spout, the lid and the handle.
  glm::vec3 viewDirection{-0.50f, 0.80f, -0.35f};
  glm::vec3 up{0.0f, 0.0f, 1.0f};
  float verticalFovDegrees = 30.0f;
  int samples = 4;  // multisampling: 1 or 4, the two counts every device supports
  // Frame this box instead of the mesh's own, so that pictures of different tessellations of
  // one surface (side by side) share one camera.
  std::optional<BoundingBox> frame;
};

// The clip-from-world matrix (Vulkan clip space) renderMesh uses for `box` and `options`: a
// tessellation for a pixel tolerance can be made for the very camera that draws it.
glm::mat4 frameViewProjection(const BoundingBox& box, const RenderOptions& options);

// Renders `mesh` with a perspective camera along options.viewDirection that fits the whole
// bounding box (corners projected, a small margin). `perTriangleValue` is empty or holds one
// value per triangle (a quad-tree level or a patch id), used by Colour::Depth and ::Patch.
// Returns width·height·4 bytes, RGBA8, rows top to bottom.
// Throws std::invalid_argument for bad options or value counts, VulkanUnavailable when the
// context's queue cannot draw, VulkanError when a Vulkan call fails.
std::vector<uint8_t> renderMesh(vk::Context& context, const TriangleMesh& mesh,
                                const std::vector<float>& perTriangleValue,
                                const RenderOptions& options);

// The sRGB colour (0..255) Colour::Depth or ::Patch gives a triangle of value `value` before
// shading (the shader's palette, shaders/layout.h): for legends. Shaded gives the porcelain.
std::array<uint8_t, 3> paletteColour(RenderOptions::Colour colour, int value);

// Per-triangle values of a tessellation for Colour::Depth and Colour::Patch.
// The level is that of the leaf the triangle lies in: its centroid in its own patch's (u, v)
// (Tessellation::trianglePatch and cornerUv, not the welded vertices' uvs) is inside exactly
// one leaf of that patch, since a leaf's triangles fan from a point inside it. Throws
// std::invalid_argument when the per-triangle arrays do not match the mesh or a centroid lies
// in no leaf (the tree is not the mesh's).
std::vector<float> triangleLevels(const Tessellation& tessellation);
std::vector<float> trianglePatchIds(const Tessellation& tessellation);

}  // namespace tessera
