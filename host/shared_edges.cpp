#include "shared_edges.h"

#include <algorithm>
#include <cstring>
#include <map>

namespace tessera {
namespace {

using CurveKey = std::vector<uint64_t>;  // the bits of every coordinate, in order

CurveKey keyOf(const std::vector<glm::dvec3>& points) {
  CurveKey key;
  for (const glm::dvec3& p : points)
    for (int c = 0; c < 3; ++c) {
      double x = p[c] == 0.0 ? 0.0 : p[c];  // -0 and +0 are the same point
      uint64_t b;
      std::memcpy(&b, &x, sizeof b);
      key.push_back(b);
    }
  return key;
}

}  // namespace

std::vector<glm::dvec3> sideControlPoints(const BezierPatch& patch, int side) {
  std::vector<glm::dvec3> points;
  const int n = patch.degreeU, m = patch.degreeV;
  switch (side) {
    case kSideV0: for (int i = 0; i <= n; ++i) points.push_back(patch.at(i, 0)); break;
    case kSideV1: for (int i = 0; i <= n; ++i) points.push_back(patch.at(i, m)); break;
    case kSideU0: for (int j = 0; j <= m; ++j) points.push_back(patch.at(0, j)); break;
    default: for (int j = 0; j <= m; ++j) points.push_back(patch.at(n, j)); break;
  }
  return points;
}

PatchTopology findSharedEdges(const std::vector<BezierPatch>& patches) {
  PatchTopology topology;
  topology.sides.resize(patches.size());
  struct Member {
    uint32_t patch;
    int side;
    bool reversed;
  };
  std::map<CurveKey, std::vector<Member>> curves;  // canonical key → sides with that curve
  for (uint32_t p = 0; p < patches.size(); ++p)
    for (int side = 0; side < 4; ++side) {
      std::vector<glm::dvec3> points = sideControlPoints(patches[p], side);
      if (std::all_of(points.begin(), points.end(), [&](const glm::dvec3& q) { return q == points[0]; })) {
        topology.sides[p][side].collapsed = true;
        ++topology.collapsedSides;
        continue;
      }
      CurveKey forward = keyOf(points);
      std::reverse(points.begin(), points.end());
      CurveKey backward = keyOf(points);
      bool reversed = backward < forward;  // canonical direction: the smaller key
      curves[reversed ? backward : forward].push_back({p, side, reversed});
    }
  for (const auto& [key, members] : curves) {
    if (members.size() < 2) continue;
    int32_t group = int32_t(topology.groupCount++);
    for (const Member& m : members) {
      topology.sides[m.patch][m.side].group = group;
      topology.sides[m.patch][m.side].reversed = m.reversed;
      ++topology.sharedSides;
    }
  }
  return topology;
}

}  // namespace tessera
