// Between the public API's plain arrays (include/tessera/tessera.h) and the library's types:
// Patch <-> BezierPatch, TriangleMesh -> Mesh, RuleOptions -> QuadtreeOptions.
#pragma once
#include <vector>

#include "geometry/patch.h"
#include "mesh/mesh.h"
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

}  // namespace tessera::api
