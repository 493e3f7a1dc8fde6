#include "trim/detail/open_edges.h"

#include <algorithm>

namespace tessera::trim_detail {

void appendReversedOpenEdges(const std::vector<FaceTriangle>& triangles, size_t vertexCount,
                             std::vector<std::pair<uint32_t, uint32_t>>& out) {
  // Each vertex's outgoing edges' far ends, grouped by vertex (counting sort), then sorted
  // within the group: the directed edges in increasing (a, b) order.
  std::vector<uint32_t> start(vertexCount + 1, 0);
  for (const FaceTriangle& t : triangles)
    for (uint32_t a : t.v) ++start[a + 1];
  for (size_t a = 0; a < vertexCount; ++a) start[a + 1] += start[a];
  std::vector<uint32_t> ends(start.back());
  std::vector<uint32_t> next(start.begin(), start.end() - 1);
  for (const FaceTriangle& t : triangles)
    for (int k = 0; k < 3; ++k) ends[next[t.v[k]]++] = t.v[(k + 1) % 3];
  for (size_t a = 0; a < vertexCount; ++a)
    std::sort(ends.data() + start[a], ends.data() + start[a + 1]);

  const auto hasEdge = [&](uint32_t a, uint32_t b) {
    return std::binary_search(ends.data() + start[a], ends.data() + start[a + 1], b);
  };
  for (uint32_t a = 0; a < vertexCount; ++a)
    for (uint32_t k = start[a]; k < start[a + 1]; ++k) {
      const uint32_t b = ends[k];
      if (k > start[a] && ends[k - 1] == b) continue;  // a repeated edge, listed once
      if (!hasEdge(b, a)) out.push_back({b, a});
    }
}

}  // namespace tessera::trim_detail
