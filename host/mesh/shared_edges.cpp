#include "mesh/shared_edges.h"

#include <algorithm>
#include <cstring>
#include <map>

namespace tessera {
namespace {

using CurveKey = std::vector<uint64_t>;  // the bits of every coordinate, in order

// Points with their weights (1 on a polynomial patch, so a polynomial side and a rational
// side with unit weights there are the same curve). Equal points with other weights are a
// different curve (the same curve reparametrised, or another one): never shared.
CurveKey keyOf(const std::vector<glm::dvec4>& points) {
  CurveKey key;
  for (const glm::dvec4& p : points)
    for (int c = 0; c < 4; ++c) {
      double x = p[c] == 0.0 ? 0.0 : p[c];  // -0 and +0 are the same point
      uint64_t b;
      std::memcpy(&b, &x, sizeof b);
      key.push_back(b);
    }
  return key;
}

// Side `side`'s control points as (x, y, z, weight), in increasing t.
std::vector<glm::dvec4> sideWeightedPoints(const BezierPatch& patch, int side) {
  BezierPatch weights = patch;  // the weights laid out as a control net, to reuse the walk
  for (size_t k = 0; k < weights.cp.size(); ++k)
    weights.cp[k] = glm::dvec3(patch.weights.empty() ? 1.0 : patch.weights[k]);
  std::vector<glm::dvec3> points = sideControlPoints(patch, side);
  std::vector<glm::dvec3> w = sideControlPoints(weights, side);
  std::vector<glm::dvec4> out;
  for (size_t k = 0; k < points.size(); ++k) out.push_back(glm::dvec4(points[k], w[k].x));
  return out;
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
      std::vector<glm::dvec4> weighted = sideWeightedPoints(patches[p], side);
      CurveKey forward = keyOf(weighted);
      std::reverse(weighted.begin(), weighted.end());
      CurveKey backward = keyOf(weighted);
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
