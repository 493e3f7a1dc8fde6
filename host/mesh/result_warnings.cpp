#include "mesh/result_warnings.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

#include "geometry/bezier.h"
#include "geometry/general_patch.h"
#include "geometry/model_frame.h"

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

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// "fp32-output" (result_warnings.h), or nothing.
std::vector<ResultWarning> fp32OutputWarning(const Tessellation& t,
                                             const std::vector<BezierPatch>& patches,
                                             double tolerance) {
  const ControlPointBox box = controlPointBox(patches);
  if (!t.mesh.positionsDouble.empty() || box.empty) return {};
  const glm::dvec3 far = glm::max(glm::abs(box.lo), glm::abs(box.hi));
  const double largest = std::max({far.x, far.y, far.z});
  const glm::dvec3 extent = box.hi - box.lo;
  const double size = std::hypot(extent.x, extent.y, extent.z);
  const double vertexMove = std::sqrt(3.0) * fp32RoundingBound(largest);
  const bool ruleT = tolerance > 0;
  const double allowed = ruleT ? kFp32OfTolerance * tolerance : kFp32OfSize * size;
  if (!(vertexMove > allowed)) return {};
  return {{"fp32-output",
           "the fp32 mesh cannot hold the accuracy asked for: its coordinates reach " +
               number(largest) + ", where fp32 rounds a vertex by up to " + number(vertexMove) +
               ", more than " +
               (ruleT ? percent(kFp32OfTolerance) + " of the tolerance " + number(tolerance)
                      : percent(kFp32OfSize) + " of the model's size " + number(size)) +
               " (write it with --precision double: OBJ, PLY)"}};
}

}  // namespace

double fp32RoundingBound(double m) {
  m = std::fabs(m);
  if (m == 0.0) return 0.0;
  if (m > double(FLT_MAX)) return INFINITY;
  int exponent = 0;
  std::frexp(m, &exponent);  // m = f·2^exponent, f in [0.5, 1): fp32's spacing there is
                             // 2^(exponent − 24), down to the subnormals' 2⁻¹⁴⁹
  return std::min(std::ldexp(1.0, std::max(exponent, -125) - 25), m);
}

double cornerPlaneDistanceRatio(const BezierPatch& model) {
  // A ratio of lengths: measured in the patch's own frame, where the squares below neither
  // under- nor overflow whatever the model's units.
  const BezierPatch patch = toLocalFrame({model}, modelFrame({model})).front();
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
                                              const std::vector<double>* geometricPerPatchMax,
                                              double tolerance) {
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
  if (tolerance > 0) {
    std::vector<double> bound(patches.size(), 0.0);
    for (const QuadLeaf& leaf : t.tree.leaves)
      if (leaf.patchIndex < patches.size())
        bound[leaf.patchIndex] = std::max(
            bound[leaf.patchIndex],
            std::isnan(leaf.flatness) ? INFINITY : double(leaf.flatness) * t.tree.boundScale);
    std::vector<size_t> unproven;
    double worst = 0;
    for (size_t p = 0; p < patches.size(); ++p)
      if (bound[p] > tolerance) {
        unproven.push_back(p);
        worst = std::max(worst, bound[p]);
      }
    if (!unproven.empty())
      warnings.push_back(
          {"unproven-patch", listPatches(unproven) + (unproven.size() == 1 ? " is" : " are") +
                                 " not proven within the tolerance " + number(tolerance) +
                                 ": rule T reached the depth or size limit with a bound of up to " +
                                 number(worst) + " (there the mesh may be farther off)"});
  }
  if (tolerance > 0 && t.stats.diagonalFans > 0)
    warnings.push_back(
        {"diagonal-fan", std::to_string(t.stats.diagonalFans) +
                             (t.stats.diagonalFans == 1 ? " leaf" : " leaves") +
                             " proven for one diagonal had to be triangulated by a fan (a folded "
                             "or repeated ring): there the mesh is proven only within the leaf's "
                             "any-triangle bound, which may be above the tolerance " +
                             number(tolerance)});
  for (ResultWarning& w : fp32OutputWarning(t, patches, tolerance))
    warnings.push_back(std::move(w));
  return warnings;
}

}  // namespace tessera
