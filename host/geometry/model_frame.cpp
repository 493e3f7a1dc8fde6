#include "geometry/model_frame.h"

#include <algorithm>

namespace tessera {
namespace {

bool hasPosition(const BezierPatch& patch, size_t k) {
  return patch.weights.empty() || patch.weights[k] > 0.0;
}

}  // namespace

void extendBox(ControlPointBox& box, const BezierPatch& patch) {
  for (size_t k = 0; k < patch.cp.size(); ++k) {
    if (!hasPosition(patch, k)) continue;
    box.lo = box.empty ? patch.cp[k] : glm::min(box.lo, patch.cp[k]);
    box.hi = box.empty ? patch.cp[k] : glm::max(box.hi, patch.cp[k]);
    box.empty = false;
  }
}

ControlPointBox controlPointBox(const std::vector<BezierPatch>& patches) {
  ControlPointBox box;
  for (const BezierPatch& patch : patches) extendBox(box, patch);
  return box;
}

ModelFrame modelFrame(const std::vector<BezierPatch>& patches) {
  return modelFrame(controlPointBox(patches));
}

ModelFrame modelFrame(const ControlPointBox& box) {
  ModelFrame frame;
  if (box.empty) return frame;
  // Halves first: lo + hi could overflow where lo/2 + hi/2 cannot (halving is exact above
  // the subnormals).
  frame.centre = 0.5 * box.lo + 0.5 * box.hi;
  const glm::dvec3 half = 0.5 * box.hi - 0.5 * box.lo;
  const double largest = std::max({half.x, half.y, half.z});
  if (largest > 0.0) frame.scale = largest;
  return frame;
}

std::vector<BezierPatch> toLocalFrame(std::vector<BezierPatch> patches, const ModelFrame& frame) {
  for (BezierPatch& patch : patches)
    for (size_t k = 0; k < patch.cp.size(); ++k)
      patch.cp[k] = hasPosition(patch, k) ? frame.toLocal(patch.cp[k]) : glm::dvec3(0.0);
  return patches;
}

}  // namespace tessera
