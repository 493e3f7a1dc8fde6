// Comparing two quad-trees leaf by leaf (by patch and path from the root).
#pragma once
#include <cstring>

#include "quadtree/quadtree.h"

namespace tessera::test {

inline bool sameLeafBits(const QuadLeaf& a, const QuadLeaf& b) {
  return a.patchIndex == b.patchIndex && a.level == b.level && a.cause == b.cause &&
         a.diagonal == b.diagonal &&
         a.path == b.path && std::memcmp(&a.rect, &b.rect, sizeof a.rect) == 0 &&
         std::memcmp(&a.linearity, &b.linearity, sizeof(float)) == 0 &&
         std::memcmp(&a.flatness, &b.flatness, sizeof(float)) == 0;
}

// True when the two trees have the same leaves, bit for bit, in the same order.
inline bool identicalTrees(const QuadtreeResult& a, const QuadtreeResult& b) {
  if (a.leaves.size() != b.leaves.size()) return false;
  for (size_t i = 0; i < a.leaves.size(); ++i)
    if (!sameLeafBits(a.leaves[i], b.leaves[i])) return false;
  return true;
}

}  // namespace tessera::test
