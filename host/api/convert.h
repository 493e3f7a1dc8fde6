// Between the public API's plain arrays (include/tessera/tessera.h) and the library's types:
// Patch <-> BezierPatch, TriangleMesh -> Mesh, RuleOptions -> QuadtreeOptions.
#pragma once
#include <vector>

#include "geometry/patch.h"
#include "mesh/mesh.h"
#include "division/view_dependent.h"
#include "quadtree/quadtree.h"
#include "tessera/tessera.h"

namespace tessera::api {

// Throws ArgumentError naming the patch when its point or weight array has the wrong length
// for its degrees (the rest is validateTessellationPatch's job).
std::vector<BezierPatch> toBezierPatches(const std::vector<Patch>& patches);
std::vector<Patch> toPatches(const std::vector<BezierPatch>& patches);

// Takes the arrays of `mesh` (moved or copied and freed): the caller's mesh is left empty.
Mesh toMesh(TriangleMesh&& mesh);

QuadtreeOptions toQuadtreeOptions(const RuleOptions& options);

// A public View as the library's Camera: its matrix and viewport, nearW left at its default.
Camera toCamera(const View& view);
// The w on the near plane (clip z = 0) of a perspective matrix, whose clip z is an affine
// function of its w (z = a·w + b, a ≠ 0, as perspectiveRH_ZO's): −b / a; `fallback` for any
// other matrix (or a near plane behind the eye).
double nearPlaneW(const glm::dmat4& viewProjection, double fallback);

}  // namespace tessera::api
