// Faces whose surface is affine in (u, v) — a plane, P(u, v) = O + u·X + v·Y — where the gap
// refinement's samples measure only rounding: a triangle's corners on the surface span the
// surface itself, so it never splits (docs/trimmed_faces.md, "Planes").
#pragma once
#include <optional>
#include <vector>

#include "trim/detail/gap_refine.h"
#include "trim/face_surface.h"
#include "trim/trimmed_face.h"

namespace tessera::trim_detail {

// Whether refineGap would leave every triangle over `vs` as it is at δ = `tolerance`, known
// without sampling: the face is one bilinear piece (equal weights or none) whose net is a
// parallelogram up to a twist T = P₀₀ − P₁₀ − P₀₁ + P₁₁, every vertex lies in its rectangle, and
// |T|/4 plus a rounding allowance is under δ. Then no triangle measures over δ.
// Proof: S = A + s·B + t·C + s·t·T in the piece's local (s, t), so at the mix Σ bᵢ(sᵢ, tᵢ) of
// the corners, Σ bᵢ S(sᵢ, tᵢ) − S(Σ bᵢ(sᵢ, tᵢ)) = T·Σ bᵢ(sᵢ − s̄)(tᵢ − t̄), a covariance of two
// [0, 1] variables, at most ¼ in size; T = 0 (a plane) makes it exactly 0. The allowance,
// 10⁻⁹ of the net's size and of the rectangle's corners' reach, covers the samples' rounding
// (a few ulps) many times over.
bool gapRefinementIdle(const TrimmedFace& face, const std::vector<FaceVertex>& vs,
                       double tolerance);

// What gapMetric (mesher.cpp) returns for the face over [lo, hi] at δ = `tolerance`, known without
// meanScales' 180 surface points: a one-piece bilinear face (no weights) nearly a parallelogram
// is flat at δ, so its metric is the ratio of its sides' speeds |B|/(u1 − u0) over
// |C|/(v1 − v0) rounded to a power of two. Empty where that cannot be told apart from rounding
// (a ratio's log₂ near a half, δ near the rounding, [lo, hi] past the rectangle).
std::optional<glm::dvec2> affineGapMetric(const TrimmedFace& face, glm::dvec2 lo, glm::dvec2 hi,
                                          double tolerance);

// What refineGap's `parametric` holds when gapRefinementIdle: per gap triangle the largest
// |Pᵢ − S(uvᵢ)| over its corners (the samples' largest parametric deviation: Σ bᵢ Pᵢ −
// S(Σ bᵢ uvᵢ) = Σ bᵢ (Pᵢ − S(uvᵢ)) on an affine S, a convex mix of the corners' offsets, whose
// largest is at a corner), −1 for the others. The corners' terms are the sampled ones bit for bit;
// the sampled interior terms add rounding (about 10⁻¹⁷ of the size), which this leaves out.
std::vector<double> cornerParametric(const FaceSurface& surface,
                                     const std::vector<FaceVertex>& vs,
                                     const std::vector<FaceTriangle>& triangles);

}  // namespace tessera::trim_detail
