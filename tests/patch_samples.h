// Test inputs shared by several test files: random bicubic patches with fixed seeds, patches
// with collapsed edges, and query grids that include patch boundaries and corners.
#pragma once
#include <cstdint>
#include <vector>

#include "geometry/patch.h"
#include "shaders/layout.h"

namespace tessera::test {

// `count` random bicubic patches: a wavy grid over [0,1]² with random heights, scaled and
// offset so coordinates span a few orders of magnitude of origin offset.
std::vector<BezierPatch> randomBicubicPatches(size_t count, uint32_t seed);

// Bicubic patches with one or two collapsed edges, like the teapot's lid top and bottom.
std::vector<BezierPatch> collapsedEdgePatches();

// An n×n grid of (u,v) on every patch (boundaries and corners included) plus `extra`
// random interior points per patch.
std::vector<gpu::EvalQuery> gridQueries(size_t patchCount, int n, int extra, uint32_t seed);

}  // namespace tessera::test
