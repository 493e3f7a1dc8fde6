// Patches of any degree 1..7 each way, polynomial or rational (BezierPatch with weights), on
// their way to the GPU: the general layout of shaders/layout.h (GeneralPatch records and one
// homogeneous control-point array). In double, patchPoint/patchDerivatives (bezier.h) honour
// weights; toRationalPatch (rational.h) gives the homogeneous form.
// Bicubic polynomial patches keep the BicubicPatch fast path (evaluator.h).
#pragma once
#include <cmath>
#include <string>
#include <vector>

#include "geometry/patch.h"
#include "shaders/layout.h"

namespace tessera {

// What the general shaders read: patch k's control points start at patches[k].firstPoint.
struct GeneralPatchSet {
  std::vector<gpu::GeneralPatch> patches;
  std::vector<gpu::vec4> points;  // homogeneous (w·x, w·y, w·z, w), rounded to float
  size_t size() const { return patches.size(); }
};

bool isRational(const BezierPatch& patch);             // has weights
bool isBicubicPolynomial(const BezierPatch& patch);    // the BicubicPatch fast path takes it

// The largest |coordinate| tessellation takes: the surface lies in its control points' hull
// (weights ≥ 0), so the mesh's fp32 positions (at most 3.4·10³⁸) hold every vertex.
constexpr double kMaxPatchCoordinate = 1e38;

// Whether a point can be a mesh position: every coordinate finite and within
// kMaxPatchCoordinate (NaN fails the comparison).
inline bool isMeshablePoint(const glm::dvec3& p) {
  return std::fabs(p.x) <= kMaxPatchCoordinate && std::fabs(p.y) <= kMaxPatchCoordinate &&
         std::fabs(p.z) <= kMaxPatchCoordinate;
}

// Throws std::invalid_argument starting with `what` (e.g. "patch 3") for a degree outside
// 1..7, a control net or weight list of the wrong size, a control point that is not finite or
// exceeds kMaxPatchCoordinate, a weight that is not finite or exceeds 1e15, a negative weight
// or a corner weight that is not positive.
void validateTessellationPatch(const BezierPatch& patch, const std::string& what);

GeneralPatchSet toGeneralPatchSet(const std::vector<BezierPatch>& patches);

// Diagonal of the control points' bounding box, weight-0 points left out.
double surfaceScale(const BezierPatch& patch);

}  // namespace tessera
