// Triangulates the region bounded by a soup of directed (u, v) edges, the region to the left of
// every edge: the gap the trimmed mesher leaves between a face's trimming loops and the
// quad-tree triangles it kept. The region may have holes, several components and pinch
// vertices (two corners of the region touching at one vertex). No vertex is added, so every
// input edge stays an edge of the output — the trim segments, shared with the neighbouring
// face, are never split (docs/trimmed_faces.md).
// Method: edges → closed loops (at a vertex with several ways on, the first clockwise from
// the way back keeps the loop on its own region); holes joined to the loop around them by a
// bridge to the nearest visible vertex; ear clipping; then Lawson flips of the unconstrained
// edges towards the Delaunay triangulation (better-shaped triangles, smaller deviation).
#pragma once
#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <utility>
#include <vector>

namespace tessera {

struct GapTriangulation {
  std::vector<std::array<uint32_t, 3>> triangles;  // counter-clockwise in (u, v)
  size_t failures = 0;  // loops that could not be closed, holes with no loop around them or
                        // no visible vertex, ear clipping stuck: 0 unless the input is bad
};

// `points`: (u, v) of each vertex id; `edges`: (from, to) ids, each directed edge once.
GapTriangulation triangulateGap(const std::vector<glm::dvec2>& points,
                                const std::vector<std::pair<uint32_t, uint32_t>>& edges);

// Lawson flips: an edge used by two triangles and not in `fixed` is flipped while the opposite
// vertex lies inside the other triangle's circumcircle and the quadrilateral is convex.
void flipTowardsDelaunay(const std::vector<glm::dvec2>& points,
                         const std::vector<std::pair<uint32_t, uint32_t>>& fixed,
                         std::vector<std::array<uint32_t, 3>>& triangles);

}  // namespace tessera
