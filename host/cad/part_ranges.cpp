#include "cad/part_ranges.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace tessera {

namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();  // not a part's
constexpr uint32_t kRest = kNone - 1;                             // a face meshed in place

// The part whose faces hold `face` (parts sorted by first face), else kRest.
uint32_t partOfFace(const std::vector<std::pair<uint32_t, uint32_t>>& byFirstFace,
                    const GlbInstances& instances, uint32_t face) {
  auto it = std::upper_bound(byFirstFace.begin(), byFirstFace.end(), std::make_pair(face, kNone));
  if (it == byFirstFace.begin()) return kRest;
  const uint32_t part = std::prev(it)->second;
  const GlbInstances::Part& p = instances.parts[part];
  return face - p.faceFirst < p.faceCount ? part : kRest;
}

}  // namespace

std::vector<PartRange> partRangesOf(const TriangleMesh& mesh,
                                    const std::vector<uint32_t>& triangleFace,
                                    const GlbInstances& instances) {
  if (instances.vertices > mesh.vertexCount() || instances.triangles > mesh.triangleCount() ||
      triangleFace.size() != mesh.triangleCount())
    throw std::logic_error("part ranges: the mesh is smaller than its instances' prefix");
  std::vector<std::pair<uint32_t, uint32_t>> byFirstFace;
  for (size_t p = 0; p < instances.parts.size(); ++p)
    byFirstFace.push_back({instances.parts[p].faceFirst, uint32_t(p)});
  std::sort(byFirstFace.begin(), byFirstFace.end());

  std::vector<PartRange> ranges(instances.parts.size());
  std::vector<uint32_t> owner(instances.vertices, kNone);
  std::vector<uint32_t> lastVertex(instances.parts.size(), 0);
  for (uint32_t t = 0; t < instances.triangles; ++t) {
    const uint32_t part = partOfFace(byFirstFace, instances, triangleFace[t]);
    if (part != kRest) {
      PartRange& range = ranges[part];
      if (range.triangleCount == 0) range.firstTriangle = t;
      if (t != range.firstTriangle + range.triangleCount)
        throw std::logic_error("part ranges: part " + std::to_string(part) +
                               "'s triangles are not consecutive");
      ++range.triangleCount;
    }
    for (int c = 0; c < 3; ++c) {
      const uint32_t v = mesh.indices[3 * size_t(t) + size_t(c)];
      if (owner[v] == kNone) owner[v] = part;
      if (owner[v] != part)
        throw std::logic_error("part ranges: vertex " + std::to_string(v) +
                               " is a part's and another's");
      if (part == kRest) continue;
      PartRange& range = ranges[part];
      if (range.vertexCount == 0) range.firstVertex = v;
      range.firstVertex = std::min(range.firstVertex, v);
      lastVertex[part] = std::max(lastVertex[part], v);
      range.vertexCount = lastVertex[part] - range.firstVertex + 1;
    }
  }
  // No other triangle's vertex inside a part's range (an unused one, from a collapsed
  // triangle, is the part's own).
  for (size_t p = 0; p < ranges.size(); ++p)
    for (uint32_t v = ranges[p].firstVertex; v < ranges[p].firstVertex + ranges[p].vertexCount; ++v)
      if (owner[v] != kNone && owner[v] != p)
        throw std::logic_error("part ranges: part " + std::to_string(p) +
                               "'s vertices are not consecutive");
  return ranges;
}

}  // namespace tessera
