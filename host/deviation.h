// How far a tessellation is from its surface. The metric is parametric: a point inside a
// triangle (a barycentric mix of its corners) is compared with the surface at the same mix of
// the corners' (u, v) — what a renderer interpolating uv would see. It bounds the geometric
// distance to the surface from above. Truth comes from the double-precision kernel.
#pragma once
#include <vector>

#include "mesh.h"
#include "patch.h"

namespace tessera {

struct DeviationReport {
  double maxDeviation = 0;   // largest distance seen, model units
  double meanDeviation = 0;  // over all samples
  size_t samples = 0;
  size_t worstTriangle = 0;
};

// Samples every triangle at the points (i, j, k)/n with i + j + k = n (n = `subdivisions`),
// corners included. The mesh needs uvs and patchIds, as tessellate() produces.
DeviationReport measureDeviation(const TriangleMesh& mesh, const std::vector<BezierPatch>& patches,
                                 int subdivisions = 4);

}  // namespace tessera
