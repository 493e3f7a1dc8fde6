#include "realtime/patch_edges.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "mesh/shared_edges.h"

namespace tessera {

PatchEdges findPatchEdges(const std::vector<BezierPatch>& patches) {
  for (size_t p = 0; p < patches.size(); ++p)
    if (patches[p].degreeU != 3 || patches[p].degreeV != 3)
      throw std::invalid_argument("real-time edges: patch " + std::to_string(p) +
                                  " is not bicubic");
  const PatchTopology topology = findSharedEdges(patches);
  PatchEdges edges;
  std::vector<int64_t> edgeOfGroup(topology.groupCount, -1);
  for (size_t p = 0; p < patches.size(); ++p) {
    std::array<uint32_t, 4> sideEdge{}, sideFlags{};
    for (int s = 0; s < 4; ++s) {
      const SideInfo& info = topology.sides[p][s];
      if (info.group >= 0 && edgeOfGroup[size_t(info.group)] >= 0) {
        sideEdge[s] = uint32_t(edgeOfGroup[size_t(info.group)]);
      } else {
        std::vector<glm::dvec3> points = sideControlPoints(patches[p], s);
        if (info.reversed) std::reverse(points.begin(), points.end());
        sideEdge[s] = uint32_t(edges.points.size());
        if (info.group >= 0) edgeOfGroup[size_t(info.group)] = sideEdge[s];
        edges.points.push_back({points[0], points[1], points[2], points[3]});
        for (const glm::dvec3& q : points) edges.gpuPoints.push_back(gpu::vec4(glm::vec3(q), 1.0f));
        edges.collapsed.push_back(info.collapsed);
      }
      sideFlags[s] = (info.reversed ? gpu::kStitchReversed : 0u) |
                     (info.collapsed ? gpu::kStitchCollapsed : 0u);
    }
    edges.sideEdge.push_back(sideEdge);
    edges.sideFlags.push_back(sideFlags);
  }
  return edges;
}

RationalBezierPatch edgeCountingPatch(const std::array<glm::dvec3, 4>& edge) {
  RationalBezierPatch patch;
  patch.degreeU = 3;
  patch.degreeV = 1;
  for (const glm::dvec3& q : edge) {
    patch.cpw.push_back(glm::dvec4(q, 1.0));
    patch.cpw.push_back(glm::dvec4(q, 1.0));
  }
  return patch;
}

}  // namespace tessera
