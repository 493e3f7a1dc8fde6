// The edges of a real-time scene: each patch side names one edge, and the sides that share a
// boundary curve (host/mesh/shared_edges.h: equal control points, either direction) name the
// same one. An edge keeps its control points once, in a canonical direction, so its segment
// count (counted once a frame from those points alone) and its vertices (evaluated from them
// at canonical parameters) are the same for both patches, bit for bit.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "division/view_dependent.h"
#include "geometry/patch.h"
#include "shaders/layout.h"

namespace tessera {

struct PatchEdges {
  std::vector<std::array<glm::dvec3, 4>> points;  // per edge, canonical order
  std::vector<gpu::vec4> gpuPoints;              // the same in fp32, 4 per edge (w = 1)
  std::vector<bool> collapsed;                   // the edge is one point (a pole)
  std::vector<std::array<uint32_t, 4>> sideEdge;   // per patch, sides V0, U1, V1, U0
  std::vector<std::array<uint32_t, 4>> sideFlags;  // per patch, gpu::kStitch*
};

// Throws std::invalid_argument for a patch that is not bicubic.
PatchEdges findPatchEdges(const std::vector<BezierPatch>& patches);

// The edge as a rational patch of bidegree (3, 1) whose two rows are the edge: viewDivisions of
// it counts an edge whose screen-space net reaches the eye plane (the others are counted from
// their four points as a curve, host/division/projected.h). Its count bounds the edge's chord
// error on screen (Filip's bound, S_uv = S_vv = 0 on a curve).
RationalBezierPatch edgeCountingPatch(const std::array<glm::dvec3, 4>& edge);

}  // namespace tessera
