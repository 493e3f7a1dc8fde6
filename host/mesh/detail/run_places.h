// A run's vertex keys → their places in LeafRun::vertices (leaf_walk.cpp): looked up once per
// leaf corner and edge point, the walk's hottest table; also the runs' border keys → their
// vertex indices in the numbering (triangulate.cpp). Open addressing with linear probing in
// one array kept at most half full, a key's slot from the high bits of one multiply: a lookup
// is mostly one slot, where the general map (hash_map.h) spent about twice the instructions
// on hashing twice and robin-hood bookkeeping. Only finds and adds; its order is never read.
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include "mesh/detail/vertex_key.h"

namespace tessera::triangulate_detail {

class RunPlaces {
 public:
  explicit RunPlaces(size_t keys) { resize(keys); }

  // Empty, with room for `keys` keys: the slots kept where they are enough and not far too
  // many. A table kept from call to call (thread_local) keeps its pages; a new one faulted
  // them in again every call, a third of the triangulator's page faults.
  void reset(size_t keys) {
    if (slots_.size() < 2 * keys + 2 || slots_.size() > 8 * keys + 64) {
      std::vector<Slot>().swap(slots_);
      count_ = 0;
      resize(keys);
      return;
    }
    std::fill(slots_.begin(), slots_.end(), Slot{{}, kEmpty});
    count_ = 0;
  }

  size_t slotCount() const { return slots_.size(); }

  // The place of `key`; `place` (then added = true) if it had none.
  uint32_t findOrAdd(const VertexKey& key, uint32_t place, bool& added) {
    for (size_t s = slotOf(key);; s = (s + 1) & mask_) {
      Slot& slot = slots_[s];
      if (slot.place == kEmpty) {
        slot = {key, place};
        added = true;
        if (++count_ * 2 > slots_.size()) resize(count_);
        return place;
      }
      if (slot.key == key) {
        added = false;
        return slot.place;
      }
    }
  }

 private:
  static constexpr uint32_t kEmpty = UINT32_MAX;
  struct Slot {
    VertexKey key;
    uint32_t place;
  };

  size_t slotOf(const VertexKey& key) const {
    const uint64_t x = (key.b ^ ((uint64_t(key.kind) << 32 | key.a) * 0xC2B2AE3D27D4EB4Full)) *
                       0x9E3779B97F4A7C15ull;
    return size_t(x >> shift_);
  }

  // Room for `keys` keys at most half full, the keys held so far placed again.
  void resize(size_t keys) {
    unsigned bits = 4;
    while ((size_t(1) << bits) < 2 * keys + 2) ++bits;
    std::vector<Slot> old;
    old.swap(slots_);
    slots_.assign(size_t(1) << bits, Slot{{}, kEmpty});
    mask_ = slots_.size() - 1;
    shift_ = 64 - bits;
    for (const Slot& slot : old)
      if (slot.place != kEmpty)
        for (size_t s = slotOf(slot.key);; s = (s + 1) & mask_)
          if (slots_[s].place == kEmpty) {
            slots_[s] = slot;
            break;
          }
  }

  std::vector<Slot> slots_;
  size_t mask_ = 0, count_ = 0;
  unsigned shift_ = 64;
};

}  // namespace tessera::triangulate_detail
