// The tessellation's vertices evaluated again in double, for --precision double: the GPU and
// the mirror give fp32 positions (about 7 digits); the same (patch, u, v) through the double
// reference (patchDerivatives, unitNormal) gives what the surface holds there.
#pragma once
#include <vector>

#include "geometry/patch.h"
#include "mesh/mesh.h"

namespace tessera {

// Fills mesh.positionsDouble and mesh.normalsDouble (when the mesh has normals) from each
// vertex's patchIds and uvs. Throws std::invalid_argument if the mesh has no uvs or patch ids
// or names a patch that `patches` lacks (a bug in the producer).
void evaluateVerticesInDouble(TriangleMesh& mesh, const std::vector<BezierPatch>& patches);

}  // namespace tessera
