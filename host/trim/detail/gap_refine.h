// One face's mesh while the trimmed mesher builds it (mesher.cpp), and the refinement of its
// gap triangles until measured within δ (docs/trimmed_faces.md, "Refine").
#pragma once
#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <utility>
#include <vector>

#include "trim/face_surface.h"
#include "trim/mesher.h"

namespace tessera::trim_detail {

// A vertex in the face's own (u, v). A trim point carries its shared id and the shared 3D
// point (on the B-rep edge, which may lie off this face's surface by the edge's gap).
struct FaceVertex {
  glm::dvec2 uv;
  glm::dvec3 position;
  int64_t sharedId = -1;  // ≥ 0: a trim point
};

struct FaceTriangle {
  std::array<uint32_t, 3> v;  // counter-clockwise in (u, v)
  bool gap = false;
};

using EdgeKey = std::pair<uint32_t, uint32_t>;
inline EdgeKey edgeKey(uint32_t a, uint32_t b) { return a < b ? EdgeKey(a, b) : EdgeKey(b, a); }

// Both of the deviations below in one pass over the samples (the surface point at each sample's
// uv, the costly part, is shared): interpolationDeviation and parametricDeviation.
struct SampledDeviations {
  double interpolation = 0, parametric = 0;
};
SampledDeviations sampledDeviations(const FaceSurface& surface, const std::vector<FaceVertex>& vs,
                                    const std::array<uint32_t, 3>& t, int n);

// sampledDeviations of each triangle in turn as refineGap takes them: the samples inside a side
// two triangles share are taken once (with n a power of two they are the same doubles in
// both). The same results as sampledDeviations, bit for bit (for tests).
std::vector<SampledDeviations> sampledDeviationsSharingSides(
    const FaceSurface& surface, const std::vector<FaceVertex>& vs,
    const std::vector<std::array<uint32_t, 3>>& triangles, int n);

// Largest |Σ bᵢ Pᵢ − S(Σ bᵢ uvᵢ)| over the barycentric samples (i, j, k)/n: the triangle against
// the surface at the same (u, v) mix, the corners' own offsets from the surface included.
double parametricDeviation(const FaceSurface& surface, const std::vector<FaceVertex>& vs,
                           const std::array<uint32_t, 3>& t, int n);
// The same samples measured by their distance to the surface (FaceSurface::distance from the
// same-uv guess, an upper bound).
double geometricDeviation(const FaceSurface& surface, const std::vector<FaceVertex>& vs,
                          const std::array<uint32_t, 3>& t, int n);

// The same with every corner moved onto the surface (Pᵢ → S(uvᵢ)): the interpolation error,
// the part that splitting the triangle reduces. parametric ≤ interpolation + the largest
// corner offset (the sample's offset term Σ bᵢ (Pᵢ − S(uvᵢ)) is a convex mix of the corners').
double interpolationDeviation(const FaceSurface& surface, const std::vector<FaceVertex>& vs,
                              const std::array<uint32_t, 3>& t, int n);

// Largest |Pᵢ − S(uvᵢ)| over the corners: for a trim point, its B-rep edge's distance from this
// face's surface (the file's edge gap); 0 for a vertex of the face's own.
// `known`, when given (one entry per vertex, −1 until measured), keeps each corner's offset
// for the next triangle that has it.
double cornerOffset(const FaceSurface& surface, const std::vector<FaceVertex>& vs,
                    const std::array<uint32_t, 3>& t, std::vector<double>* known = nullptr);

// The geometric counterpart of interpolationDeviation (corners on the surface).
double interpolationDistance(const FaceSurface& surface, const std::vector<FaceVertex>& vs,
                             const std::array<uint32_t, 3>& t, int n);

// Whether interpolationDistance(…) ≤ limit, as the refinement asks it: samples whose surface
// point already lies within limit less a rounding allowance of their target need no
// closest-point search (the search starts there and only lowers the distance).
bool interpolationWithin(const FaceSurface& surface, const std::vector<FaceVertex>& vs,
                         const std::array<uint32_t, 3>& t, int n, double limit);

struct GapRefineOptions {
  double tolerance = 0;         // δ
  int subdivisions = 8;         // samples per triangle side
  int maxRounds = 24;
  glm::dvec2 metric{1.0, 1.0};  // (u, v) scales for shapes and lengths (mesher.cpp, gapMetric)
  GapMeasure measure = GapMeasure::Geometric;  // a triangle within δ parametrically is
                                              // not searched geometrically
};

// Splits gap triangles whose interpolation deviation exceeds δ: a sliver (height below 1% of its
// longest side) whose longest side is not a trim segment gives that side up to a flip with the
// triangle across it (a midpoint split would keep both halves on the line); otherwise the
// longest side that is not a trim segment is split at its (u, v) midpoint together with every
// triangle across it (kept or gap: no T-junction), or, with three trim sides, the centroid is
// added. Trim segments are never split: the neighbouring face uses them as they are.
// Returns the number of splits and flips and the gap triangles still over δ when the rounds ran
// out (GapRefineOptions::maxRounds; 0 when it finished). `parametric`, when given, receives per final triangle
// its parametricDeviation where the refinement sampled it (every gap triangle it judged), −1
// elsewhere: the stats need not sample those again. `trimEdges`: the trim segments' keys,
// sorted and distinct (looked up by binary search).
struct GapRefineResult {
  size_t changes = 0;     // splits and flips
  size_t unfinished = 0;  // gap triangles left over δ
};
GapRefineResult refineGap(const FaceSurface& surface, std::vector<FaceVertex>& vs,
                 std::vector<FaceTriangle>& triangles, const std::vector<EdgeKey>& trimEdges,
                 const GapRefineOptions& options, std::vector<double>* parametric = nullptr);

}  // namespace tessera::trim_detail
