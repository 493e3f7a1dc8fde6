// Topological checks of triangle meshes for the watertightness tests.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

#include "mesh/mesh.h"

namespace tessera::test {

struct EdgeCensus {
  std::map<std::pair<uint32_t, uint32_t>, int> directed;    // (a, b) → times used a→b
  std::map<std::pair<uint32_t, uint32_t>, int> undirected;  // (min, max) → times used
  size_t boundaryEdges = 0;      // used by one triangle
  size_t manifoldEdges = 0;      // used by two
  size_t overusedEdges = 0;      // used by three or more
  size_t inconsistentEdges = 0;  // used twice in the same direction
  size_t degenerateTriangles = 0;
  size_t usedVertices = 0;
};

inline EdgeCensus censusOf(const TriangleMesh& mesh, double minArea) {
  EdgeCensus c;
  std::map<uint32_t, bool> used;
  for (size_t t = 0; t < mesh.indices.size(); t += 3) {
    uint32_t v[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
    glm::dvec3 a(mesh.positions[v[0]]), b(mesh.positions[v[1]]), d(mesh.positions[v[2]]);
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2] ||
        0.5 * glm::length(glm::cross(b - a, d - a)) <= minArea)
      ++c.degenerateTriangles;
    for (int k = 0; k < 3; ++k) {
      uint32_t p = v[k], q = v[(k + 1) % 3];
      used[p] = true;
      ++c.directed[{p, q}];
      ++c.undirected[{std::min(p, q), std::max(p, q)}];
    }
  }
  for (const auto& [edge, count] : c.undirected) {
    if (count == 1) ++c.boundaryEdges;
    if (count == 2) {
      ++c.manifoldEdges;
      if (c.directed[{edge.first, edge.second}] != 1) ++c.inconsistentEdges;
    }
    if (count > 2) ++c.overusedEdges;
  }
  c.usedVertices = used.size();
  return c;
}

// T-junctions: a vertex on the mesh's boundary (an end of some edge only one triangle uses)
// within `eps` of the inside of another such edge (strictly between its ends, 1e-6 of its
// length and more than `eps` away from them: a vertex within eps of an end is at that end at
// this resolution). There the neighbour's side is split and this one is not, so the surface has
// a crack however small; the split side's vertex is on the crack, so it ends open edges itself.
// A vertex all of whose edges have two triangles is inside the surface, whatever its distance
// to an open edge (where a sheet is thinner than eps: the teaspoon's handle tip). Vertices are
// binned in a uniform grid of cells the mean open edge's length; `largestGap` gets the longest
// such edge.
inline size_t tJunctionCount(const TriangleMesh& mesh, const EdgeCensus& c, double eps,
                             double* largestGap = nullptr) {
  std::vector<std::pair<uint32_t, uint32_t>> open;
  double total = 0;
  for (const auto& [edge, count] : c.undirected)
    if (count == 1) {
      open.push_back(edge);
      total += glm::length(glm::dvec3(mesh.positions[edge.first]) -
                           glm::dvec3(mesh.positions[edge.second]));
    }
  if (largestGap) *largestGap = 0;
  if (open.empty()) return 0;
  const double cell = std::max(total / double(open.size()), 8 * eps);
  const auto cellOf = [&](const glm::dvec3& p) { return glm::floor(p / cell); };
  const auto key = [](const glm::dvec3& k) {
    return (int64_t(k.x) * 73856093) ^ (int64_t(k.y) * 19349663) ^ (int64_t(k.z) * 83492791);
  };
  std::vector<bool> onBoundary(mesh.positions.size(), false);
  for (const auto& [a, b] : open) onBoundary[a] = onBoundary[b] = true;
  std::unordered_map<int64_t, std::vector<uint32_t>> bins;
  for (uint32_t v = 0; v < mesh.positions.size(); ++v)
    if (onBoundary[v]) bins[key(cellOf(glm::dvec3(mesh.positions[v])))].push_back(v);
  size_t found = 0;
  for (const auto& [a, b] : open) {
    const glm::dvec3 pa(mesh.positions[a]), pb(mesh.positions[b]), d = pb - pa;
    const double length2 = glm::dot(d, d);
    if (length2 == 0) continue;
    const glm::dvec3 lo = cellOf(glm::min(pa, pb) - eps), hi = cellOf(glm::max(pa, pb) + eps);
    bool junction = false;
    for (double x = lo.x; x <= hi.x && !junction; ++x)
      for (double y = lo.y; y <= hi.y && !junction; ++y)
        for (double z = lo.z; z <= hi.z && !junction; ++z) {
          const auto bin = bins.find(key({x, y, z}));
          if (bin == bins.end()) continue;
          for (uint32_t v : bin->second) {
            if (v == a || v == b) continue;
            const glm::dvec3 p(mesh.positions[v]);
            const double t = glm::dot(p - pa, d) / length2;
            if (t > 1e-6 && t < 1 - 1e-6 && glm::length(p - (pa + t * d)) <= eps &&
                glm::length(p - pa) > eps && glm::length(p - pb) > eps) {
              junction = true;
              break;
            }
          }
        }
    if (junction) {
      ++found;
      if (largestGap) *largestGap = std::max(*largestGap, std::sqrt(length2));
    }
  }
  return found;
}

}  // namespace tessera::test
