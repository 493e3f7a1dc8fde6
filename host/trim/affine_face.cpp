#include "trim/detail/affine_face.h"

#include <algorithm>
#include <cmath>

namespace tessera::trim_detail {

// The samples' rounding against the allowance: each sample is a few sums and products of
// numbers no larger than the net's points and the rectangle's corners (a few ulps, 10⁻¹⁵ of
// them); 10⁻⁹ leaves a million-fold margin while staying far below any δ a caller asks for.
constexpr double kRoundingShare = 1e-9;

bool gapRefinementIdle(const TrimmedFace& face, const std::vector<FaceVertex>& vs,
                       double tolerance) {
  if (face.pieces.size() != 1) return false;
  const BezierPatchPiece& piece = face.pieces[0];
  const BezierPatch& patch = piece.patch;
  if (patch.degreeU != 1 || patch.degreeV != 1 || patch.cp.size() != 4) return false;
  if (!patch.weights.empty() &&
      !std::all_of(patch.weights.begin(), patch.weights.end(),
                   [&](double w) { return w == patch.weights[0]; }))
    return false;
  const glm::dvec3 &p00 = patch.at(0, 0), &p10 = patch.at(1, 0), &p01 = patch.at(0, 1),
                   &p11 = patch.at(1, 1);
  const double twist = glm::length(p00 - p10 - p01 + p11);
  double size = 0;
  for (const glm::dvec3& p : patch.cp) size = std::max(size, glm::length(p));
  const double speed = std::max({glm::length(p10 - p00), glm::length(p11 - p01)}) /
                           (piece.u1 - piece.u0) +
                       std::max({glm::length(p01 - p00), glm::length(p11 - p10)}) /
                           (piece.v1 - piece.v0);
  const double reach = std::max({std::abs(piece.u0), std::abs(piece.u1), std::abs(piece.v0),
                                 std::abs(piece.v1)});
  // Outside its rectangle the surface is clamped (FaceSurface), no longer affine: a vertex may
  // pass it by rounding (a quad-tree corner's u0 + 1·(u1 − u0)), which moves its point by at
  // most speed·margin, twice for a sample's mix; more, and the face is not taken.
  const double margin = kRoundingShare * reach;
  for (const FaceVertex& v : vs)
    if (!(v.uv.x >= piece.u0 - margin && v.uv.x <= piece.u1 + margin &&
          v.uv.y >= piece.v0 - margin && v.uv.y <= piece.v1 + margin))
      return false;
  // The covariance bound ¼ grows to ¼·(1 + 2εu)(1 + 2εv) over the rectangle grown by the margin.
  const double grownU = 1 + 2 * margin / (piece.u1 - piece.u0),
               grownV = 1 + 2 * margin / (piece.v1 - piece.v0);
  const double bound = 0.25 * grownU * grownV * twist +
                       kRoundingShare * (size + speed * reach) + 2 * speed * margin;
  return std::isfinite(bound) && bound < tolerance;
}

std::vector<double> cornerParametric(const FaceSurface& surface,
                                     const std::vector<FaceVertex>& vs,
                                     const std::vector<FaceTriangle>& triangles) {
  // Each corner's squared offset once: a vertex has about six triangles.
  std::vector<double> offset2(vs.size(), -1.0);
  std::vector<double> parametric(triangles.size(), -1.0);
  for (size_t t = 0; t < triangles.size(); ++t) {
    if (!triangles[t].gap) continue;
    double worst2 = 0;
    for (const uint32_t v : triangles[t].v) {
      if (offset2[v] < 0) {
        const glm::dvec3 d = vs[v].position - surface.point(vs[v].uv);
        offset2[v] = glm::dot(d, d);
      }
      worst2 = std::max(worst2, offset2[v]);
    }
    parametric[t] = std::sqrt(worst2);  // √ of the largest square: sampledDeviations' value
  }
  return parametric;
}

}  // namespace tessera::trim_detail
