#include "trim/detail/affine_face.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace tessera::trim_detail {

// The samples' rounding against the allowance: each sample is a few sums and products of
// numbers no larger than the net's points and the rectangle's corners (a few ulps, 10⁻¹⁵ of
// them); 10⁻⁹ leaves a million-fold margin while staying far below any δ a caller asks for.
constexpr double kRoundingShare = 1e-9;
// The same for meanScales' second differences, divided by h² = 10⁻⁶ of the extent²: a tighter
// share (still thousands of ulps) so that fine δ keeps the shortcut.
constexpr double kMetricRoundingShare = 1e-12;

namespace {

// A one-piece bilinear face's net: P(s, t) = P₀₀ + s·B + t·C + s·t·T on the piece's local [0, 1]².
struct BilinearNet {
  const BezierPatchPiece* piece = nullptr;
  glm::dvec3 b{0.0}, c{0.0};
  double twist = 0;  // |T|
  double size = 0;   // the largest |Pᵢⱼ|
  double speed = 0;  // bounds |∂P/∂u| + |∂P/∂v| in the face's (u, v) over the piece
  double reach = 0;  // the largest |u|, |v| of the rectangle's sides
};

std::optional<BilinearNet> bilinearNet(const TrimmedFace& face, bool allowWeights) {
  if (face.pieces.size() != 1) return std::nullopt;
  const BezierPatchPiece& piece = face.pieces[0];
  const BezierPatch& patch = piece.patch;
  if (patch.degreeU != 1 || patch.degreeV != 1 || patch.cp.size() != 4) return std::nullopt;
  if (!patch.weights.empty() &&
      (!allowWeights || !std::all_of(patch.weights.begin(), patch.weights.end(),
                                     [&](double w) { return w == patch.weights[0]; })))
    return std::nullopt;
  BilinearNet net;
  net.piece = &piece;
  const glm::dvec3 &p00 = patch.at(0, 0), &p10 = patch.at(1, 0), &p01 = patch.at(0, 1),
                   &p11 = patch.at(1, 1);
  net.b = p10 - p00, net.c = p01 - p00;
  net.twist = glm::length(p00 - p10 - p01 + p11);
  for (const glm::dvec3& p : patch.cp) net.size = std::max(net.size, glm::length(p));
  net.speed = std::max(glm::length(p10 - p00), glm::length(p11 - p01)) / (piece.u1 - piece.u0) +
              std::max(glm::length(p01 - p00), glm::length(p11 - p10)) / (piece.v1 - piece.v0);
  net.reach = std::max({std::abs(piece.u0), std::abs(piece.u1), std::abs(piece.v0),
                        std::abs(piece.v1)});
  return net;
}

bool within(glm::dvec2 uv, const BezierPatchPiece& piece, double margin) {
  return uv.x >= piece.u0 - margin && uv.x <= piece.u1 + margin && uv.y >= piece.v0 - margin &&
         uv.y <= piece.v1 + margin;
}

}  // namespace

bool gapRefinementIdle(const TrimmedFace& face, const std::vector<FaceVertex>& vs,
                       double tolerance) {
  const std::optional<BilinearNet> net = bilinearNet(face, true);
  if (!net) return false;
  const BezierPatchPiece& piece = *net->piece;
  // Outside its rectangle the surface is clamped (FaceSurface), no longer affine: a vertex may
  // pass it by rounding (a quad-tree corner's u0 + 1·(u1 − u0)), which moves its point by at
  // most speed·margin, twice for a sample's mix; more, and the face is not taken.
  const double margin = kRoundingShare * net->reach;
  for (const FaceVertex& v : vs)
    if (!within(v.uv, piece, margin)) return false;
  // The covariance bound ¼ grows to ¼·(1 + 2εu)(1 + 2εv) over the rectangle grown by the margin.
  const double grownU = 1 + 2 * margin / (piece.u1 - piece.u0),
               grownV = 1 + 2 * margin / (piece.v1 - piece.v0);
  const double bound = 0.25 * grownU * grownV * net->twist +
                       kRoundingShare * (net->size + net->speed * net->reach) +
                       2 * net->speed * margin;
  return std::isfinite(bound) && bound < tolerance;
}

std::optional<glm::dvec2> affineGapMetric(const TrimmedFace& face, glm::dvec2 lo, glm::dvec2 hi,
                                          double tolerance) {
  const std::optional<BilinearNet> net = bilinearNet(face, false);
  if (!net) return std::nullopt;
  const BezierPatchPiece& piece = *net->piece;
  const glm::dvec2 extent = hi - lo;
  // meanScales' grid, 1/12 of the extent in from [lo, hi] less its step h = 10⁻³ of it, inside
  // the rectangle: no point clamped.
  const double margin = kRoundingShare * net->reach;
  if (!(within(lo, piece, margin) && within(hi, piece, margin) &&
        margin < 1e-3 * std::min(extent.x, extent.y)))
    return std::nullopt;
  // Flat: a bilinear surface is linear along u at fixed v and along v at fixed u, and
  // meanScales' second differences keep the other coordinate, so its bending is rounding alone,
  // at most `noise`/h² with h = 10⁻³ of the extent (noise: 10⁻¹², thousands of the ulps that
  // the stencil's points and sums carry); gapMetric calls a direction flat when
  // √(8δ/b) ≥ the extent, i.e. b ≤ 8δ/extent², here with a factor 2 to spare.
  const double noise = kMetricRoundingShare * (net->size + net->speed * net->reach);
  if (!(2 * noise * 1e6 <= 8 * tolerance)) return std::nullopt;
  // Then gapMetric's ratio is the mean speeds' along u over v, |B + t·T|/(u1 − u0) over
  // |C + s·T|/(v1 − v0) at the grid's t and s: |B|/|C| scaled, up to |T| and the rounding of the
  // central differences (a step of 10⁻³ of the extent: 10⁻¹² relative and what the reach and the
  // net's size add to it). Rounded to a power of two as gapMetric does, unless log₂ of it lies
  // so near a half that the error could round it the other way.
  const double shortest = std::min(glm::length(net->b), glm::length(net->c));
  if (!(shortest > 0)) return std::nullopt;
  const double relative =
      net->twist / shortest +
      kRoundingShare * (1 + net->reach / std::min(extent.x, extent.y) + net->size / shortest);
  const double ratio = (glm::length(net->b) / (piece.u1 - piece.u0)) /
                       (glm::length(net->c) / (piece.v1 - piece.v0));
  const double exponent = std::log2(ratio), nearest = std::round(exponent);
  if (!(std::isfinite(exponent) && std::abs(exponent - nearest) < 0.5 - 4 * relative - 1e-9))
    return std::nullopt;
  return glm::dvec2(std::exp2(nearest), 1.0);
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
