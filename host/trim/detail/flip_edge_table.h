// The edge → triangles table of one gap's Delaunay flips (gap_triangulate.cpp): open
// addressing with linear probing and backward-shift erase over one power-of-two array kept per
// thread and sized once for the gap. A flip erases one edge and adds one, so the table never
// grows; most gaps are a few triangles, where the hashed map's buckets (allocated per gap) and
// the short list searched from the front (quadratic in the triangles) both cost more than the
// flips. The flips ask only for an edge's users, so any table gives the same flips. Each entry
// also carries whether its edge is constrained (an input edge, never flipped), which the flips
// asked a sorted list for, by binary search, five times a flip.
#pragma once
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "common/small_id_list.h"

namespace tessera::trim_detail {

class FlipEdgeTable {
 public:
  struct Entry {
    SmallIdList ids;     // the triangles using the edge
    bool fixed = false;  // a constrained edge
  };

  // Room for every edge of `triangles` triangles (at most 3 a triangle) at a load of ≤ ¾. The
  // slots are the thread's: at most one table may be alive on a thread at a time.
  explicit FlipEdgeTable(size_t triangles) : slots_(buffer()) {
    size_t capacity = 16;
    bits_ = 4;
    while (capacity < 4 * triangles + 8) capacity *= 2, ++bits_;
    mask_ = capacity - 1;
    if (slots_.size() < capacity) slots_.resize(capacity);
    for (size_t k = 0; k < capacity; ++k) slots_[k].key = kEmpty;
  }
  FlipEdgeTable(const FlipEdgeTable&) = delete;
  FlipEdgeTable& operator=(const FlipEdgeTable&) = delete;

  // The key's entry, added (no triangles, not fixed) if absent. Keys are edges (smaller id in
  // the high word), never kEmpty.
  Entry& operator[](uint64_t key) {
    size_t k = home(key);
    while (slots_[k].key != kEmpty) {
      if (slots_[k].key == key) return slots_[k].entry;
      k = (k + 1) & mask_;
    }
    slots_[k].key = key;
    slots_[k].entry = Entry();
    return slots_[k].entry;
  }
  Entry* find(uint64_t key) {
    for (size_t k = home(key); slots_[k].key != kEmpty; k = (k + 1) & mask_)
      if (slots_[k].key == key) return &slots_[k].entry;
    return nullptr;
  }
  void erase(uint64_t key) {
    size_t hole = home(key);
    while (slots_[hole].key != key) {
      if (slots_[hole].key == kEmpty) return;
      hole = (hole + 1) & mask_;
    }
    // Backward shift: an entry after the hole moves into it unless its home lies cyclically in
    // (hole, entry], where the probe from its home would not pass the hole.
    for (size_t next = (hole + 1) & mask_; slots_[next].key != kEmpty; next = (next + 1) & mask_) {
      const size_t want = home(slots_[next].key);
      const bool staysAfterHole = hole <= next ? (hole < want && want <= next)
                                               : (hole < want || want <= next);
      if (staysAfterHole) continue;
      slots_[hole] = std::move(slots_[next]);
      hole = next;
    }
    slots_[hole].key = kEmpty;
    slots_[hole].entry = Entry();
  }
  template <class F>
  void forEach(F&& f) {
    for (size_t k = 0; k <= mask_; ++k)
      if (slots_[k].key != kEmpty) f(slots_[k].key, slots_[k].entry);
  }

 private:
  static constexpr uint64_t kEmpty = ~uint64_t(0);
  struct Slot {
    uint64_t key = kEmpty;
    Entry entry;
  };
  static std::vector<Slot>& buffer() {
    thread_local std::vector<Slot> slots;
    return slots;
  }
  size_t home(uint64_t key) const { return size_t((key * 0x9E3779B97F4A7C15ull) >> (64 - bits_)); }

  std::vector<Slot>& slots_;
  size_t mask_ = 0;
  int bits_ = 0;
};

}  // namespace tessera::trim_detail
