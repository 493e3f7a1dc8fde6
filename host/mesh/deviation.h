// How far a tessellation is from its surface, by one of two metrics (every report says which):
// - parametric: a point inside a triangle (a barycentric mix of its corners) is compared with
//   the surface at the same mix of the corners' (u, v) — what a renderer interpolating uv
//   would see. It bounds the geometric distance from above, loosely where the
//   parametrisation is uneven (collapsed edges).
// - geometric: the distance from that point to the triangle's own patch, by a closest-point
//   search started at the parametric guess (closest_point.h). What "deviation from the true
//   surface" means for a mesh viewed without its uv, and what Open CASCADE's deflection bounds.
// Truth comes from the double-precision kernel.
#pragma once
#include <vector>

#include "mesh/mesh.h"
#include "geometry/patch.h"

namespace tessera {

enum class DeviationMetric { Parametric, Geometric };
const char* deviationMetricName(DeviationMetric metric);  // "parametric", "geometric"

struct DeviationReport {
  double maxDeviation = 0;   // largest distance seen, model units
  double meanDeviation = 0;  // over all samples
  size_t samples = 0;
  size_t worstTriangle = 0;
  // Per patch (index = patch): largest and mean distance over its triangles' samples
  // (0 for a patch without triangles).
  std::vector<double> perPatchMax;
  std::vector<double> perPatchMean;
  std::vector<size_t> perPatchSamples;
  std::vector<size_t> perPatchWorstTriangle;  // the first triangle reaching perPatchMax
};

struct Tessellation;

// Samples every triangle at the points (i, j, k)/n with i + j + k = n (n = `subdivisions`),
// corners included, against the triangle's own patch at its corners' (u, v) there.
// (It takes the Tessellation, not only its mesh: a vertex welded across patches keeps one
// patch's (u, v), so the mesh alone cannot say where a triangle lies on its own patch.)
// The corners are mesh.positionsDouble where the mesh has them (what --precision double
// writes), else the fp32 positions: the deviation of the mesh as written.
DeviationReport measureDeviation(const Tessellation& tessellation,
                                 const std::vector<BezierPatch>& patches, int subdivisions = 4,
                                 DeviationMetric metric = DeviationMetric::Parametric);

}  // namespace tessera
