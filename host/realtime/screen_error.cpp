// Screen-space error of a real-time frame, a rule-T mesh or the peer's captured triangles
// (measureScreenError, frame.h): triangle samples against the double-precision surface, both
// projected to pixels.
#include <algorithm>
#include <array>

#include "geometry/bezier.h"
#include "realtime/detail/stitch_mirror.h"
#include "realtime/frame.h"

namespace tessera {
namespace {

struct Projected {
  glm::dvec2 pixel;
  double w;  // clip w: depth in front of the eye
};

Projected project(const Camera& camera, const glm::dvec3& world) {
  const glm::dvec4 h = camera.viewProjection * glm::dvec4(world, 1.0);
  return {glm::dvec2((h.x / h.w + 1.0) * 0.5 * camera.width,
                     (h.y / h.w + 1.0) * 0.5 * camera.height),
          h.w};
}

bool onScreen(const Camera& camera, const glm::dvec2& p) {
  return p.x >= 0.0 && p.x <= camera.width && p.y >= 0.0 && p.y <= camera.height;
}

struct Corner {
  glm::dvec3 world;
  glm::dvec2 uv;
  Projected screen;
};

// Both errors of one triangle at its (i, j, k)/n samples, into `report`.
void measureTriangle(const std::array<Corner, 3>& c, const BezierPatch& patch,
                     const Camera& camera, int n, ScreenErrorReport& report) {
  for (const Corner& corner : c)
    if (corner.screen.w <= camera.nearW) return;
  if (!onScreen(camera, c[0].screen.pixel) && !onScreen(camera, c[1].screen.pixel) &&
      !onScreen(camera, c[2].screen.pixel))
    return;
  ++report.triangles;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const double a = double(i) / n, b = double(j) / n, g = 1.0 - a - b;
      const glm::dvec2 uv = a * c[0].uv + b * c[1].uv + g * c[2].uv;
      const glm::dvec2 truth = project(camera, patchPoint(patch, uv.x, uv.y)).pixel;
      const glm::dvec2 affine =
          a * c[0].screen.pixel + b * c[1].screen.pixel + g * c[2].screen.pixel;
      const glm::dvec2 perspective =
          project(camera, a * c[0].world + b * c[1].world + g * c[2].world).pixel;
      report.maxAffinePixels = std::max(report.maxAffinePixels, glm::length(affine - truth));
      report.maxPerspectivePixels =
          std::max(report.maxPerspectivePixels, glm::length(perspective - truth));
      ++report.samples;
    }
}

}  // namespace

ScreenErrorReport measureScreenError(const RealtimeFrame& frame,
                                     const std::vector<BezierPatch>& patches,
                                     const Camera& camera, int subdivisions) {
  ScreenErrorReport report;
  const int n = std::max(1, subdivisions);
  for (const gpu::StitchPatch& record : frame.records) {
    const std::vector<gpu::vec2> uv = mirror::stitchVertexParams(record);
    auto corner = [&](uint32_t index) {
      const glm::dvec3 world(glm::vec3(frame.vertices[index].position));
      return Corner{world, glm::dvec2(uv[index - record.firstVertex]), project(camera, world)};
    };
    const uint32_t triangles = mirror::stitchTriangleCount(record);
    for (uint32_t t = 0; t < triangles; ++t) {
      const uint32_t* corners = frame.indices + record.firstIndex + 3 * t;
      measureTriangle({corner(corners[0]), corner(corners[1]), corner(corners[2])},
                      patches[record.patchIndex], camera, n, report);
    }
  }
  return report;
}

ScreenErrorReport measureScreenError(const Tessellation& t, const std::vector<BezierPatch>& patches,
                                     const Camera& camera, int subdivisions) {
  ScreenErrorReport report;
  const int n = std::max(1, subdivisions);
  for (size_t tri = 0; tri < t.trianglePatch.size(); ++tri) {
    std::array<Corner, 3> c;
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 world(t.mesh.positions[t.mesh.indices[3 * tri + k]]);
      c[size_t(k)] = Corner{world, glm::dvec2(t.cornerUv[3 * tri + k]), project(camera, world)};
    }
    measureTriangle(c, patches[t.trianglePatch[tri]], camera, n, report);
  }
  return report;
}

ScreenErrorReport measureScreenError(const std::vector<gpu::TessPeerTriangle>& peerTriangles,
                                     const std::vector<BezierPatch>& patches,
                                     const Camera& camera, int subdivisions) {
  ScreenErrorReport report;
  const int n = std::max(1, subdivisions);
  for (const gpu::TessPeerTriangle& t : peerTriangles) {
    const glm::dvec2 uv[3] = {{t.uv01.x, t.uv01.y}, {t.uv01.z, t.uv01.w}, {t.uv2.x, t.uv2.y}};
    std::array<Corner, 3> c;
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 world(glm::vec3(t.corners[k]));
      c[size_t(k)] = Corner{world, uv[k], project(camera, world)};
    }
    measureTriangle(c, patches.at(t.patchIndex), camera, n, report);
  }
  return report;
}

}  // namespace tessera
