// Near-coincident points from the two sides of a line made one vertex (near_points.h): which
// key each merged point's vertex is, and where on its line a leaf corner merged into another
// point now lies. Built once before the leaf walk; the walk looks keys up (find, resolve), so
// these stay inline.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "common/hash_map.h"
#include "mesh/detail/line_points.h"
#include "mesh/detail/seam_vertices.h"

namespace tessera::triangulate_detail {

// The corners of a line merged into another point of it, sorted by t, with that point's t.
using MovedCorners = std::vector<std::pair<float, float>>;

struct NearPointMerges {
  // Key → the key of the vertex it is merged into. Flat tables (hash_map.h): the walk looks
  // up every leaf corner here and every leaf edge in moved*; nothing depends on their order.
  HashMap<VertexKey, VertexKey, VertexKeyHash> merged;
  HashMap<uint64_t, MovedCorners> movedAlongU, movedAlongV;  // lines with merges
  std::vector<MovedCorners> sharedMoved;  // per group (empty when nothing merged)

  VertexKey find(VertexKey key) const {
    for (auto it = merged.find(key); it != merged.end() && !(it->second == key);
         it = merged.find(key))
      key = it->second;
    return key;
  }

  // The key a vertex is merged into (itself if none); notes that the leaf met a merged one.
  VertexKey resolve(const VertexKey& key, bool& touchesMerge) const {
    if (merged.empty()) return key;
    const VertexKey r = find(key);
    if (!(r == key)) touchesMerge = true;
    return r;
  }
};

// Merges the near points of every line (on `threads` threads where lines are independent),
// then keeps in `lines` only the points that stay vertices of their own. Hands out position
// ids (seams.baseKey) in the order merging meets them.
NearPointMerges mergeNearPoints(LinePoints& lines, SeamVertices& seams, size_t leafCount,
                                unsigned threads);

}  // namespace tessera::triangulate_detail
