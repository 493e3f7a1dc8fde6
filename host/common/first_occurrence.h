// Which item first had each key, for items met in a fixed order (vertices numbered in leaf
// order, positions welded to the first one): one hash table per shard of the keys, the
// shards on threads, so the lookups of a large serial pass run on all cores. The answer is
// the sequence's, so it does not depend on the thread count.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/hash_map.h"
#include "common/parallel_for.h"

namespace tessera {

// Per item i of 0 … count − 1, the first item with i's key (i itself if none came before).
// forEachKey(visit) must call visit(i, key) for every item in increasing i; it is called once
// per shard, the shards at once on up to `threads` threads (0: all). expectedKeys: about how
// many distinct keys there are (the tables' reserve).
template <class Key, class Hash, class ForEachKey>
std::vector<uint32_t> firstOccurrences(size_t count, size_t expectedKeys,
                                       const ForEachKey& forEachKey, unsigned threads) {
  std::vector<uint32_t> first(count);
  // A thread pays for itself from a few thousand items on (a small mesh takes one).
  constexpr size_t kItemsPerShard = 4096;
  const unsigned shards = unsigned(
      std::max<size_t>(1, std::min<size_t>(resolveThreadCount(threads), count / kItemsPerShard)));
  parallelParts(shards, [&](unsigned shard) {
    HashMap<Key, uint32_t, Hash> seen;
    seen.max_load_factor(0.8f);  // half the memory of tsl's 0.5: fewer pages to fault in
    seen.reserve(expectedKeys / shards + expectedKeys / shards / 8);
    forEachKey([&](size_t i, const Key& key) {
      // The shard by another mix of the hash than the table's (MixedHash).
      if (shards > 1 && (uint64_t(Hash{}(key)) * 0xC2B2AE3D27D4EB4Full >> 40) % shards != shard)
        return;
      first[i] = seen.try_emplace(key, uint32_t(i)).first->second;
    });
  });
  return first;
}

}  // namespace tessera
