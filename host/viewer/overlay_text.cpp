#include "viewer/overlay_text.h"

#include <stb_easy_font.h>

#include <algorithm>

namespace tessera::viewer {
namespace {

constexpr float kTextGrey = 1.0f;
constexpr float kBandGrey = 0.12f;

void addQuad(std::vector<DrawVertex>& out, const glm::vec2 (&corners)[4], float grey) {
  static const int kTriangles[6] = {0, 1, 2, 0, 2, 3};
  for (int k = 0; k < 6; ++k)
    out.push_back({glm::vec3(corners[kTriangles[k]], 0.0f), grey, glm::vec3(0, 0, -1),
                   float(k % 3)});
}

}  // namespace

std::vector<DrawVertex> overlayTriangles(const std::string& text, int scale) {
  // stb_easy_font writes 4 vertices of 16 bytes (x, y, z, RGBA8) per quad; ~270 bytes a
  // character is its documented worst case.
  std::vector<char> quads(text.size() * 300 + 64);
  std::string mutableText = text;  // stb_easy_font takes char*
  const int count = stb_easy_font_print(0, 0, mutableText.data(), nullptr, quads.data(),
                                        int(quads.size()));
  std::vector<DrawVertex> out;
  const float margin = 4.0f, s = float(scale);
  for (int q = 0; q < count; ++q) {
    glm::vec2 corners[4];
    for (int k = 0; k < 4; ++k) {
      const float* v = reinterpret_cast<const float*>(&quads[size_t(q * 4 + k) * 16]);
      corners[k] = glm::vec2(margin + s * v[0], margin + s * v[1]);
    }
    addQuad(out, corners, kTextGrey);
  }
  const float width = float(stb_easy_font_width(mutableText.data())) * s + 2 * margin;
  const float height = float(stb_easy_font_height(mutableText.data())) * s + 2 * margin;
  addQuad(out, {{0, 0}, {width, 0}, {width, height}, {0, height}}, kBandGrey);
  return out;
}

gpu::MeshDrawPush overlayPush(int width, int height) {
  gpu::MeshDrawPush push{};
  // clip = (2x/W − 1, 2y/H − 1, z, 1): Vulkan's clip y already points down, as pixels do.
  push.viewProjection[0] = gpu::vec4(2.0f / float(std::max(width, 1)), 0, 0, 0);
  push.viewProjection[1] = gpu::vec4(0, 2.0f / float(std::max(height, 1)), 0, 0);
  push.viewProjection[2] = gpu::vec4(0, 0, 1, 0);
  push.viewProjection[3] = gpu::vec4(-1, -1, 0, 1);
  push.colourMode = gpu::kColourFlat;
  return push;
}

}  // namespace tessera::viewer
