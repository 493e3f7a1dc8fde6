// Which patch boundaries are shared. Two boundary curves are the same curve when their
// control points and weights (1 on a polynomial patch) are equal bit for bit, in the same or
// in reverse order; a boundary whose control points are all equal is collapsed to a point
// (the teapot's lid top and bottom).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "geometry/patch.h"

namespace tessera {

// Sides of the parameter square, counter-clockwise. The parameter t along a side is u on
// sides 0 and 2 and v on sides 1 and 3, increasing from 0 to 1.
enum PatchSide : uint8_t { kSideV0 = 0, kSideU1 = 1, kSideV1 = 2, kSideU0 = 3 };

struct SideInfo {
  int32_t group = -1;     // shared-edge group, -1 when no other side has this curve
  bool reversed = false;  // t runs opposite to the group's canonical direction
  bool collapsed = false; // the side is a single point
};

struct PatchTopology {
  std::vector<std::array<SideInfo, 4>> sides;  // per patch
  size_t groupCount = 0;
  size_t sharedSides = 0;     // sides in some group
  size_t collapsedSides = 0;
};

// Control points of side `side` of `patch` in increasing t.
std::vector<glm::dvec3> sideControlPoints(const BezierPatch& patch, int side);
// The first of them (the side's point at t = 0), without building the list: a collapsed
// side's one position, asked for at each leaf corner on it.
const glm::dvec3& sideStartPoint(const BezierPatch& patch, int side);

PatchTopology findSharedEdges(const std::vector<BezierPatch>& patches);

}  // namespace tessera
