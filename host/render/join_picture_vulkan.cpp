#include "render/join_picture.h"

#include "loop/limit.h"
#include "render/offscreen.h"

namespace tessera {
namespace {

constexpr int kPictureLevels = 3;

// The limit surface of a control mesh as a triangle mesh; each control face's value goes to
// all its 4^levels children (refineLoopTopology numbers face f's children 4f .. 4f + 3).
void addLimitSurface(const LoopShape& shape, const glm::dvec3& offset,
                     const std::vector<float>& faceValue, TriangleMesh& mesh,
                     std::vector<float>& values) {
  LoopLevels levels = refineLoop(buildLoopTopology(shape.topology), shape.positions, kPictureLevels);
  const LoopTopology& fine = levels.topology.back();
  const auto limit = loopLimitPositions(fine, levels.positions.back());
  const auto normals = loopLimitNormals(fine, levels.positions.back());
  const uint32_t first = uint32_t(mesh.positions.size());
  for (uint32_t v = 0; v < fine.vertexCount; ++v) {
    mesh.positions.push_back(glm::vec3(limit[v] + offset));
    mesh.normals.push_back(glm::vec3(normals[v]));
  }
  for (uint32_t i : fine.triangles) mesh.indices.push_back(first + i);
  const size_t children = size_t(1) << (2 * kPictureLevels);
  for (size_t f = 0; f < fine.faceCount(); ++f) values.push_back(faceValue[f / children]);
}

std::vector<uint8_t> renderPanel(vk::Context& context, const TriangleMesh& mesh,
                                 const std::vector<float>& values, int width, int height) {
  RenderOptions options;
  options.width = width;
  options.height = height;
  options.colour = RenderOptions::Colour::Patch;
  return renderMesh(context, mesh, values, options);
}

}  // namespace

std::vector<uint8_t> renderJoinPicture(vk::Context& context, const LoopShape& first,
                                       const LoopShape& second, const LoopJoinResult& joined,
                                       int panelWidth, int height) {
  auto constant = [](const LoopShape& s, float value) {
    return std::vector<float>(s.topology.triangles.size() / 3, value);
  };
  std::vector<std::vector<uint8_t>> panels;
  // Inputs apart: the second moved along x beyond the first's box.
  {
    TriangleMesh mesh;
    std::vector<float> values;
    glm::dvec3 loA(1e300), hiA(-1e300), loB(1e300), hiB(-1e300);
    for (const auto& p : first.positions) loA = glm::min(loA, p), hiA = glm::max(hiA, p);
    for (const auto& p : second.positions) loB = glm::min(loB, p), hiB = glm::max(hiB, p);
    addLimitSurface(first, glm::dvec3(0.0), constant(first, 0), mesh, values);
    const double gap = 0.2 * glm::length(hiA - loA);
    addLimitSurface(second, glm::dvec3(hiA.x + gap - loB.x, 0, 0), constant(second, 1), mesh, values);
    panels.push_back(renderPanel(context, mesh, values, panelWidth, height));
  }
  {  // Placement.
    TriangleMesh mesh;
    std::vector<float> values;
    addLimitSurface(first, glm::dvec3(0.0), constant(first, 0), mesh, values);
    addLimitSurface(second, glm::dvec3(0.0), constant(second, 1), mesh, values);
    panels.push_back(renderPanel(context, mesh, values, panelWidth, height));
  }
  {  // Result: faces by the side of their corners (mixed: the bridge).
    TriangleMesh mesh;
    std::vector<float> values, faceValue;
    const auto& t = joined.mesh.topology.triangles;
    for (size_t f = 0; f < t.size(); f += 3) {
      const uint8_t s = joined.side[t[f]];
      faceValue.push_back(joined.side[t[f + 1]] == s && joined.side[t[f + 2]] == s ? float(s) : 2.0f);
    }
    addLimitSurface(joined.mesh, glm::dvec3(0.0), faceValue, mesh, values);
    panels.push_back(renderPanel(context, mesh, values, panelWidth, height));
  }
  std::vector<uint8_t> picture(size_t(3) * panelWidth * height * 4);
  for (int row = 0; row < height; ++row)
    for (int p = 0; p < 3; ++p)
      std::copy_n(&panels[p][size_t(row) * panelWidth * 4], size_t(panelWidth) * 4,
                  &picture[(size_t(row) * 3 * panelWidth + size_t(p) * panelWidth) * 4]);
  return picture;
}

}  // namespace tessera
