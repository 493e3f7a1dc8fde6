// A rule-T leaf's ring without a centre vertex (issue 15). The ring is the leaf's four corners
// and the vertices its finer neighbours (and shared patch sides) put on its sides, counter-
// clockwise. Rule T's bound holds for every triangle whose corners lie in the leaf's rectangle
// (docs/quadtree.md, "Rule T: tolerance"), so the ring of n vertices needs only n − 2
// triangles, where the fan around a centre vertex spends n.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace tessera {

// Triangulates the polygon `ring` (points on the boundary of the rectangle lo..hi, counter-
// clockwise, each with a coordinate exactly lo or hi) into ring.size() − 2 counter-clockwise
// triangles (indices into ring) that cover the polygon exactly (the rectangle, when the ring
// holds its four corners as a leaf's does), with no vertex added and no triangle of zero
// area: none has its three corners on one side of the rectangle (points on a side are
// collinear). Ear clipping on the convex ring: an ear is a corner with its two ring
// neighbours, refused when the three lie on one side or when the ring left over would lie on
// one side; among the others the one whose new edge is shortest in the leaf's own unit-square
// coordinates goes first (ties: first in ring order), which keeps triangles compact.
// Returns false, with `triangles` empty, when a point is off the boundary, the points are not
// distinct and counter-clockwise, or they are fewer than 3 or all on one side (the caller then
// keeps its fan).
bool triangulateRectangleRing(const std::vector<glm::vec2>& ring, glm::vec2 lo, glm::vec2 hi,
                              std::vector<std::array<uint32_t, 3>>& triangles);

// The same, keeping every edge along one diagonal of the rectangle: `diagonal` 1 (the main,
// lo–hi: every edge has Δu·Δv ≥ 0) or 2 (the anti-diagonal, (hi.x, lo.y)–(lo.x, hi.y): Δu·Δv ≤
// 0), as a rule-T leaf's bound may require (gpu::kTolerance*Diagonal, docs/quadtree.md, "One
// diagonal"); 0 = any, triangulateRectangleRing itself. The ring is cut along that diagonal
// (both its corners must be in the ring) and each half, whose points lie on two sides that
// meet at a corner, is triangulated alone: every edge inside a half joins two points that are
// ordered the same way in u and in v (opposite ways for the anti-diagonal). Still n − 2
// triangles. Returns false, `triangles` empty, where triangulateRectangleRing would or a
// corner of the diagonal is missing.
bool triangulateRectangleRingAlong(const glm::vec2* ring, size_t n, glm::vec2 lo, glm::vec2 hi,
                                   uint32_t diagonal,
                                   std::vector<std::array<uint32_t, 3>>& triangles);
inline bool triangulateRectangleRingAlong(const std::vector<glm::vec2>& ring, glm::vec2 lo,
                                          glm::vec2 hi, uint32_t diagonal,
                                          std::vector<std::array<uint32_t, 3>>& triangles) {
  return triangulateRectangleRingAlong(ring.data(), ring.size(), lo, hi, diagonal, triangles);
}

}  // namespace tessera
