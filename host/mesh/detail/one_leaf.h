// The triangulation of a tree that is one leaf over one patch (a plane's face, most faces of a
// CAD model): its four corners and two triangles, written directly. triangulateLeaves' setup
// (shared sides, folds, line points, near merges, the walk, the numbering) costs tens of
// thousands of instructions a call and decides nothing here when the patch's four corners are
// distinct points and no side folds: then no side is shared or collapsed, each line holds only
// the leaf's two corners a whole side apart (never merged, near_points.h), and the walk meets
// the corners in ring order.
#pragma once
#include <optional>
#include <vector>

#include "mesh/triangulate.h"

namespace tessera::triangulate_detail {

// triangulateLeaves' mesh for this case, bit for bit; empty where the case does not apply (the
// general path then runs): more than one leaf or patch, a leaf short of [0, 1]², a diagonal other
// than the main one (its ring triangulation), corners not distinct, a folded side, a scope that
// passes a topology, asks for seam keys or leaves the patch out.
std::optional<ParamMesh> triangulateOneLeaf(const std::vector<QuadLeaf>& leaves,
                                            const std::vector<BezierPatch>& patches,
                                            const TriangulationScope& scope);

}  // namespace tessera::triangulate_detail
