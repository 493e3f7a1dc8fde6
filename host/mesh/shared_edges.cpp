#include "mesh/shared_edges.h"

#include <algorithm>
#include <cstring>

namespace tessera {
namespace {

// Visits the control-point indices of side `side` in increasing t: the one statement of a
// side's order, for its index list and its points alike.
template <typename Visit>
void forEachSideIndex(const BezierPatch& patch, int side, Visit&& visit) {
  const int n = patch.degreeU, m = patch.degreeV;
  const auto index = [m](int i, int j) { return size_t(i * (m + 1) + j); };
  switch (side) {
    case kSideV0: for (int i = 0; i <= n; ++i) visit(index(i, 0)); break;
    case kSideV1: for (int i = 0; i <= n; ++i) visit(index(i, m)); break;
    case kSideU0: for (int j = 0; j <= m; ++j) visit(index(0, j)); break;
    default: for (int j = 0; j <= m; ++j) visit(index(n, j)); break;
  }
}

// The control-point indices of side `side` in increasing t, into `out` (cleared first).
void sideIndices(const BezierPatch& patch, int side, std::vector<size_t>& out) {
  out.clear();
  forEachSideIndex(patch, side, [&](size_t k) { out.push_back(k); });
}

uint64_t bitsOf(double x) {
  if (x == 0.0) x = 0.0;  // -0 and +0 are the same point
  uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// A side's key: the bits of every point's (x, y, z, weight), weight 1 on a polynomial patch
// (so a polynomial side and a rational side with unit weights there are the same curve),
// points in the order of `indices`. Equal points with other weights are a different curve
// (the same curve reparametrised, or another one): never shared.
constexpr size_t kWordsPerPoint = 4;

template <typename Indices>
void appendKey(const BezierPatch& patch, const Indices& indices, std::vector<uint64_t>& out) {
  size_t at = out.size();
  out.resize(at + kWordsPerPoint * indices.size());
  for (size_t k : indices) {
    const glm::dvec3& p = patch.cp[k];
    out[at++] = bitsOf(p.x);
    out[at++] = bitsOf(p.y);
    out[at++] = bitsOf(p.z);
    out[at++] = bitsOf(patch.weights.empty() ? 1.0 : patch.weights[k]);
  }
}

// The key of the same points in reverse order: `key`'s points (four words each) back to front.
void reverseKey(const std::vector<uint64_t>& key, std::vector<uint64_t>& out) {
  out.resize(key.size());
  for (size_t b = 0, n = key.size(); b < n; b += kWordsPerPoint)
    std::copy_n(&key[b], kWordsPerPoint, &out[n - kWordsPerPoint - b]);
}

}  // namespace

std::vector<glm::dvec3> sideControlPoints(const BezierPatch& patch, int side) {
  std::vector<glm::dvec3> points;
  points.reserve(size_t(side == kSideV0 || side == kSideV1 ? patch.degreeU : patch.degreeV) + 1);
  forEachSideIndex(patch, side, [&](size_t k) { points.push_back(patch.cp[k]); });
  return points;
}

const glm::dvec3& sideStartPoint(const BezierPatch& patch, int side) {
  const glm::dvec3* first = nullptr;
  forEachSideIndex(patch, side, [&](size_t k) {
    if (!first) first = &patch.cp[k];
  });
  return *first;
}

PatchTopology findSharedEdges(const std::vector<BezierPatch>& patches) {
  PatchTopology topology;
  topology.sides.resize(patches.size());
  // Every side's canonical key (the smaller of its two directions) in one pool: a map from
  // key to sides allocated a vector per key and per side. Sorting the sides by key, then by
  // when they were seen, gives the map's groups in the map's order, members in its order.
  struct Member {
    size_t begin, end;  // its key in `keys`
    uint64_t head;      // the key's first word, compared first without going to `keys`
    uint32_t patch;
    int side;
    bool reversed;
  };
  std::vector<uint64_t> keys, forward, backward;
  std::vector<Member> members;
  std::vector<size_t> indices;
  members.reserve(4 * patches.size());
  size_t keyWords = 0;  // 4 words a side point, each point on two sides
  for (const BezierPatch& patch : patches) keyWords += 8 * size_t(patch.degreeU + patch.degreeV + 2);
  keys.reserve(keyWords);
  for (uint32_t p = 0; p < patches.size(); ++p)
    for (int side = 0; side < 4; ++side) {
      const BezierPatch& patch = patches[p];
      sideIndices(patch, side, indices);
      const glm::dvec3& first = patch.cp[indices[0]];
      if (std::all_of(indices.begin(), indices.end(),
                      [&](size_t k) { return patch.cp[k] == first; })) {
        topology.sides[p][side].collapsed = true;
        ++topology.collapsedSides;
        continue;
      }
      forward.clear();
      appendKey(patch, indices, forward);
      reverseKey(forward, backward);
      const bool reversed = backward < forward;  // canonical direction: the smaller key
      const std::vector<uint64_t>& key = reversed ? backward : forward;
      members.push_back({keys.size(), keys.size() + key.size(), key[0], p, side, reversed});
      keys.insert(keys.end(), key.begin(), key.end());
    }
  const auto keyLess = [&](const Member& a, const Member& b) {
    if (a.head != b.head) return a.head < b.head;
    return std::lexicographical_compare(keys.begin() + a.begin, keys.begin() + a.end,
                                        keys.begin() + b.begin, keys.begin() + b.end);
  };
  // A stable sort's order is the one order of the keys that keeps ties as seen, so any stable
  // sort gives it: insertion for a face's few sides (std::stable_sort allocates a buffer).
  if (members.size() <= 32) {
    for (size_t k = 1; k < members.size(); ++k)
      for (size_t j = k; j > 0 && keyLess(members[j], members[j - 1]); --j)
        std::swap(members[j], members[j - 1]);
  } else {
    std::stable_sort(members.begin(), members.end(), keyLess);
  }
  for (size_t first = 0; first < members.size();) {
    size_t last = first + 1;
    while (last < members.size() && !keyLess(members[first], members[last])) ++last;
    if (last - first >= 2) {
      const int32_t group = int32_t(topology.groupCount++);
      for (size_t k = first; k < last; ++k) {
        SideInfo& info = topology.sides[members[k].patch][members[k].side];
        info.group = group;
        info.reversed = members[k].reversed;
        ++topology.sharedSides;
      }
    }
    first = last;
  }
  return topology;
}

}  // namespace tessera
