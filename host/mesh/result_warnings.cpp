#include "mesh/result_warnings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "geometry/bezier.h"
#include "geometry/general_patch.h"

namespace tessera {
namespace {

// "patches 0, 4 and 9" (the first few, then how many more).
std::string listPatches(const std::vector<size_t>& patches) {
  constexpr size_t kShown = 5;
  std::string text = patches.size() == 1 ? "patch " : "patches ";
  for (size_t k = 0; k < std::min(patches.size(), kShown); ++k) {
    if (k > 0) text += k + 1 == patches.size() ? " and " : ", ";
    text += std::to_string(patches[k]);
  }
  if (patches.size() > kShown) text += " and " + std::to_string(patches.size() - kShown) + " more";
  return text;
}

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g%%", 100.0 * fraction);
  return text;
}

}  // namespace

double cornerPlaneDistanceRatio(const BezierPatch& patch) {
  const glm::dvec3 c00 = patchPoint(patch, 0, 0), c10 = patchPoint(patch, 1, 0),
                   c01 = patchPoint(patch, 0, 1), c11 = patchPoint(patch, 1, 1);
  const glm::dvec3 normal = glm::cross(c11 - c00, c01 - c10);
  const double scale = surfaceScale(patch);
  if (!(glm::length(normal) > 1e-12 * scale * scale) || !(scale > 0)) return 0.0;
  const glm::dvec3 n = glm::normalize(normal);
  const glm::dvec3 centre = 0.25 * (c00 + c10 + c01 + c11);
  double farthest = 0;
  for (int i = 0; i < kFlatnessSamples; ++i)
    for (int j = 0; j < kFlatnessSamples; ++j) {
      const double u = double(i) / (kFlatnessSamples - 1), v = double(j) / (kFlatnessSamples - 1);
      farthest = std::max(farthest, std::abs(glm::dot(patchPoint(patch, u, v) - centre, n)));
    }
  return farthest / scale;
}

std::vector<ResultWarning> findResultWarnings(const Tessellation& t,
                                              const std::vector<BezierPatch>& patches,
                                              const std::vector<double>* geometricPerPatchMax) {
  std::vector<ResultWarning> warnings;
  const TriangleMesh& mesh = t.mesh;
  if (mesh.triangleCount() == 0) {
    warnings.push_back({"no-triangles", "the mesh has no triangles (" +
                                            std::to_string(patches.size()) +
                                            " patches in, every one collapsed or none given)"});
    return warnings;
  }
  if (!mesh.normals.empty()) {
    std::vector<char> zero(mesh.vertexCount(), 0);
    size_t count = 0;
    for (uint32_t v : mesh.indices)
      if (!zero[v] && mesh.normals[v] == glm::vec3(0.0f)) zero[v] = 1, ++count;
    if (count > 0)
      warnings.push_back({"zero-normals", std::to_string(count) +
                                              (count == 1 ? " vertex has" : " vertices have") +
                                              " no normal (written as 0 0 0): the surface has no "
                                              "tangent plane there"});
  }
  std::vector<size_t> triangles(patches.size(), 0);
  for (uint32_t p : t.trianglePatch)
    if (p < patches.size()) ++triangles[p];
  std::vector<size_t> flattened;
  double worstFlattened = 0;
  for (size_t p = 0; p < patches.size(); ++p) {
    if (triangles[p] == 0 || triangles[p] > 2) continue;
    const double ratio = cornerPlaneDistanceRatio(patches[p]);
    if (ratio > kFlattenedFraction) {
      flattened.push_back(p);
      worstFlattened = std::max(worstFlattened, ratio);
    }
  }
  if (!flattened.empty())
    warnings.push_back({"flattened-patch",
                        listPatches(flattened) + " got at most 2 triangles though the surface " +
                            "lies up to " + percent(worstFlattened) +
                            " of the patch's size off its corners' plane: the rule's samples "
                            "missed the bump (try a smaller --flatness, or rule T)"});
  if (geometricPerPatchMax) {
    std::vector<size_t> far;
    double worst = 0;
    for (size_t p = 0; p < patches.size() && p < geometricPerPatchMax->size(); ++p) {
      const double scale = surfaceScale(patches[p]);
      const double ratio = scale > 0 ? (*geometricPerPatchMax)[p] / scale : 0.0;
      if (ratio > kLargeDeviationFraction) {
        far.push_back(p);
        worst = std::max(worst, ratio);
      }
    }
    if (!far.empty())
      warnings.push_back({"large-deviation", listPatches(far) +
                                                 (far.size() == 1 ? " deviates" : " deviate") +
                                                 " from the surface by up to " + percent(worst) +
                                                 " of the patch's size (measured)"});
  }
  return warnings;
}

}  // namespace tessera
