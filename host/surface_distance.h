// The geometric deviation of a tessellation: how far points of its triangles are from the true
// surface — the closest point of the triangle's own patch, found by Newton from the point's
// parametric guess (deviation.h compares with the surface at the same barycentric mix of the
// corners' (u, v) instead, an upper bound of this one). This is what CAD meshers such as Open
// CASCADE's BRepMesh promise ("linear deflection"), so bench/bench_occt.cpp measures both
// meshes with both metrics.
#pragma once
#include <vector>

#include "deviation.h"
#include "patch.h"

namespace tessera {

struct Tessellation;

// Samples every triangle at the points (i, j, k)/n with i + j + k = n, like measureDeviation,
// and reports the distance of each to its patch (the closest point over [0,1]², or at worst
// the parametric guess: never more than measureDeviation's value). Runs on all cores.
// perPatchMax/perPatchMean are filled as in measureDeviation.
DeviationReport measureSurfaceDistance(const Tessellation& tessellation,
                                       const std::vector<BezierPatch>& patches,
                                       int subdivisions = 4);

// The closest point of `patch` to `point` by projected Newton on ½|S(u,v) − p|² from `start`,
// kept inside [0,1]²; returns the smallest distance seen (at most the distance at `start`).
double distanceToPatch(const BezierPatch& patch, const glm::dvec3& point, glm::dvec2 start);

}  // namespace tessera
