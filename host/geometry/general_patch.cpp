#include "geometry/general_patch.h"

#include <cmath>
#include <stdexcept>

#include "geometry/rational.h"
#include "geometry/surface_normal.h"

namespace tessera {

bool isRational(const BezierPatch& patch) { return !patch.weights.empty(); }

bool isBicubicPolynomial(const BezierPatch& patch) {
  return patch.degreeU == 3 && patch.degreeV == 3 && patch.cp.size() == 16 && !isRational(patch);
}

void validateTessellationPatch(const BezierPatch& p, const std::string& what) {
  auto fail = [&](const std::string& why) { throw std::invalid_argument(what + " " + why); };
  if (p.degreeU < 1 || p.degreeU > kMaxDegree || p.degreeV < 1 || p.degreeV > kMaxDegree)
    fail("has degree " + std::to_string(p.degreeU) + "x" + std::to_string(p.degreeV) +
         ": adaptive tessellation takes degrees 1..7 in u and v");
  const size_t count = size_t(p.degreeU + 1) * size_t(p.degreeV + 1);
  if (p.cp.size() != count) fail("has " + std::to_string(p.cp.size()) + " control points, not " + std::to_string(count));
  // The GPU sees the model in a local frame (model_frame.h), so any magnitude is exact
  // enough there; the mesh's fp32 positions must hold it (kMaxPatchCoordinate). NaN/Inf
  // poison a tree.
  for (const glm::dvec3& c : p.cp)
    if (!isMeshablePoint(c))
      fail("has a control point that is not finite or exceeds 1e38 (the mesh is fp32)");
  if (!isRational(p)) return;
  if (p.weights.size() != count) fail("has " + std::to_string(p.weights.size()) + " weights, not " + std::to_string(count));
  for (double w : p.weights)
    if (!std::isfinite(w) || w < 0.0 || w > 1e15)
      fail("has a weight that is negative, not finite or exceeds 1e15");
  const int m = p.degreeV;
  for (int i : {0, p.degreeU})
    for (int j : {0, m})
      if (!(p.weights[size_t(i * (m + 1) + j)] > 0.0)) fail("has a corner weight that is not positive");
}

GeneralPatchSet toGeneralPatchSet(const std::vector<BezierPatch>& patches) {
  GeneralPatchSet set;
  set.patches.reserve(patches.size());
  for (const BezierPatch& p : patches) {
    set.patches.push_back({uint32_t(p.degreeU), uint32_t(p.degreeV), isRational(p) ? 1u : 0u,
                           uint32_t(set.points.size())});
    for (const glm::dvec4& h : toRationalPatch(p).cpw) set.points.push_back(gpu::vec4(h));
  }
  return set;
}

double surfaceScale(const BezierPatch& patch) {
  return isRational(patch) ? controlNetDiagonal(toRationalPatch(patch))
                           : controlNetDiagonal(patch);
}

}  // namespace tessera
