// Which item first had each key, for items met in a fixed order (corner positions welded to
// the first one, mesh_cleanup.cpp): one hash table per shard of the keys, the
// shards on threads, so the lookups of a large serial pass run on all cores. The answer is
// the sequence's, so it does not depend on the thread count.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <utility>
#include <vector>

#include "common/hash_map.h"
#include "common/parallel_for.h"

namespace tessera {

namespace first_occurrence_detail {

// The shards' tables, kept from call to call. A table of a large mesh is megabytes that malloc
// hands back to the kernel when it is freed (heap trimming, or munmap above the mmap threshold)
// and that fault in again, page by page, in the next call: rule T's vertex numbering and
// welding took ~40% of a tessellation's page faults that way (bench/HISTORY.md, "Where the
// time after the tree goes"). A
// table comes back cleared (its buckets kept); one far larger than a call needs is freed
// rather than kept, so a small mesh after a large one does not clear megabytes, and a few
// tables at most wait here.
template <class Key, class Hash>
class TablePool {
 public:
  using Table = HashMap<Key, uint32_t, Hash>;

  static TablePool& instance() {
    static TablePool pool;
    return pool;
  }

  // A cleared table with room for `keys` keys at the load factor the caller uses.
  Table take(size_t keys) {
    Table table;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!kept_.empty()) {
        table = std::move(kept_.back());
        kept_.pop_back();
      }
    }
    if (table.bucket_count() > 4 * keys + 64) table = Table();  // far too large for this call
    table.clear();
    table.max_load_factor(0.8f);  // half the memory of tsl's 0.5: fewer pages to fault in
    table.reserve(keys);
    return table;
  }

  void give(Table&& table) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (kept_.size() < kKept && table.bucket_count() <= kKeptBuckets)
      kept_.push_back(std::move(table));
  }

 private:
  static constexpr size_t kKept = 4;  // one per shard on this machine's cores, and a spare
  // What an embedding program may find held between its calls: a table of a huge mesh is
  // freed, not kept (2¹⁸ buckets: a few MiB each, the tea set's at 10⁻³ well inside).
  static constexpr size_t kKeptBuckets = size_t(1) << 18;
  std::mutex mutex_;
  std::vector<Table> kept_;
};

}  // namespace first_occurrence_detail

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
    auto& pool = first_occurrence_detail::TablePool<Key, Hash>::instance();
    HashMap<Key, uint32_t, Hash> seen =
        pool.take(expectedKeys / shards + expectedKeys / shards / 8);
    forEachKey([&](size_t i, const Key& key) {
      // The shard by another mix of the hash than the table's (MixedHash).
      if (shards > 1 && (uint64_t(Hash{}(key)) * 0xC2B2AE3D27D4EB4Full >> 40) % shards != shard)
        return;
      first[i] = seen.try_emplace(key, uint32_t(i)).first->second;
    });
    pool.give(std::move(seen));
  });
  return first;
}

}  // namespace tessera
