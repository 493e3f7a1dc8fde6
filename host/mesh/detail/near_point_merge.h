// Near-coincident points from the two sides of a line made one vertex (near_points.h): which
// key each merged point's vertex is, and where on its line a leaf corner merged into another
// point now lies. Built once before the leaf walk; the walk looks keys up (find, resolve), so
// these stay inline.
#pragma once
#include <atomic>
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
  // Key → the key of the vertex it is merged into (a flat table, hash_map.h; nothing depends
  // on its order).
  HashMap<VertexKey, VertexKey, VertexKeyHash> merged;
  // Per line of LinePoints::alongU and alongV, by its number there: 1 + its place in `moved`
  // when a point of it was merged into another, else 0; both empty when nothing merged. The
  // walk finds a leaf edge's moved corners by its line's number, and knows that a leaf corner
  // on a line without any needs no look-up in `merged`: every leaf corner is a point of its
  // lines, and each line's merged points are listed (listRepresentatives).
  std::vector<uint32_t> movedOfU, movedOfV;
  std::vector<MovedCorners> moved;
  std::vector<MovedCorners> sharedMoved;  // per group (empty when nothing merged)

  // The corners merged away on line `line` of alongU (or alongV), or null.
  const MovedCorners* movedOn(bool alongU, uint32_t line) const {
    const std::vector<uint32_t>& of = alongU ? movedOfU : movedOfV;
    return line < of.size() && of[line] != 0 ? &moved[of[line] - 1] : nullptr;
  }

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

// Per line of one direction (by its number in LinePoints::alongU or alongV), or per shared-side
// group, its near pairs.
using LinePairs = std::vector<std::vector<std::pair<float, float>>>;

// Sorts and folds the points of every line of `lines` (LinePoints::alongU when alongU, else
// alongV) and finds each line's near pairs (nearPairs); a shared, collapsed or folded side's
// line gets none (merged by the side's own rules). Reads only these lines and the patches, so
// the two directions may be searched at once (collectLinePoints' hook).
LinePairs findLinePairs(LineIndex& lines, const SeamVertices& seams, bool alongU);

// Per shared-side group (LinePoints::shared), its points sorted and folded and their near
// pairs, the surface evaluated on the group's side in LinePoints::groupSide. Reads only the
// shared sides and the patches, so it may run beside findLinePairs (collectLinePoints' hook),
// and on several threads at once: each takes the groups no other has taken, one at a time,
// so the thread done first with its direction takes most of them.
class SharedSidePairs {
 public:
  explicit SharedSidePairs(size_t groups) : pairs_(groups) {}
  // Finds the pairs of every group not yet taken; returns when none is left.
  void findUntaken(LinePoints& lines, const SeamVertices& seams);
  const LinePairs& pairs() const { return pairs_; }

 private:
  std::atomic<size_t> next_{0};
  LinePairs pairs_;
};

// Merges the lines' near pairs (findLinePairs) and the shared sides' (SharedSidePairs),
// then keeps in `lines` only the points that stay vertices of their own. Hands out position
// ids (seams.baseKey) in the order merging meets them.
NearPointMerges mergeNearPoints(LinePoints& lines, SeamVertices& seams, const LinePairs& pairsU,
                                const LinePairs& pairsV, const LinePairs& pairsShared,
                                size_t leafCount);

}  // namespace tessera::triangulate_detail
