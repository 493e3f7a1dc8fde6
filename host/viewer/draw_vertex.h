// One vertex of the viewer's un-indexed triangle lists: the two vec4 inputs of
// shaders/mesh.vert.glsl (the layout host/render/offscreen_vulkan.cpp uses too).
#pragma once
#include <glm/glm.hpp>

namespace tessera::viewer {

struct DrawVertex {
  glm::vec3 position;
  float value;  // the triangle's palette value, or its grey level with kColourFlat
  glm::vec3 normal;
  float corner;  // 0, 1 or 2: becomes the barycentric coordinate (wireframe)
};
static_assert(sizeof(DrawVertex) == 32, "DrawVertex: two vec4 attributes");

}  // namespace tessera::viewer
