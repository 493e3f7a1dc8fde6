// A hash map from a mesh edge's 64-bit key (two 32-bit vertex ids, the smaller in the high
// word) to a value, stored flat: open addressing with linear probing, erase by backward shift
// (Knuth, TAOCP vol. 3, 6.4, algorithm R). std::unordered_map allocated a node per edge; the
// gap triangulation and refinement build one map per face, and malloc was a third of the gap
// triangulation's time (perf, bench_cad --tessera-only). No iteration order is promised (the
// callers sort what they walk); references die at the next insertion.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace tessera {

template <class Value>
class EdgeHashMap {
 public:
  static constexpr uint64_t kNoEdge = ~uint64_t(0);  // no edge has both ids 2³² − 1

  size_t size() const { return count_; }

  // Room for `count` entries without growing.
  void reserve(size_t count) {
    size_t capacity = 16;
    while (capacity < 2 * count) capacity *= 2;
    if (capacity > keys_.size()) rehash(capacity);
  }

  // The entry of `key`, made with Value() if there is none.
  Value& operator[](uint64_t key) {
    if (2 * (count_ + 1) > keys_.size()) rehash(keys_.empty() ? 16 : 2 * keys_.size());
    size_t i = home(key);
    while (keys_[i] != kNoEdge && keys_[i] != key) i = (i + 1) & mask_;
    if (keys_[i] == kNoEdge) {
      keys_[i] = key;
      values_[i] = Value();
      ++count_;
    }
    return values_[i];
  }

  const Value* find(uint64_t key) const {
    const size_t i = slotOf(key);
    return i == kMissing ? nullptr : &values_[i];
  }
  bool contains(uint64_t key) const { return slotOf(key) != kMissing; }

  void erase(uint64_t key) {
    size_t hole = slotOf(key);
    if (hole == kMissing) return;
    --count_;
    // Entries after the hole whose home is not cyclically in (hole, j] move back into it.
    for (size_t j = (hole + 1) & mask_; keys_[j] != kNoEdge; j = (j + 1) & mask_) {
      const size_t h = home(keys_[j]);
      const bool staysPut = hole <= j ? (hole < h && h <= j) : (hole < h || h <= j);
      if (staysPut) continue;
      keys_[hole] = keys_[j];
      values_[hole] = std::move(values_[j]);
      hole = j;
    }
    keys_[hole] = kNoEdge;
    values_[hole] = Value();
  }

  // visit(key, value) for every entry, in no promised order.
  template <class Visit>
  void forEach(Visit visit) const {
    for (size_t i = 0; i < keys_.size(); ++i)
      if (keys_[i] != kNoEdge) visit(keys_[i], values_[i]);
  }

 private:
  static constexpr size_t kMissing = ~size_t(0);

  size_t home(uint64_t key) const {
    return size_t((key * 0x9E3779B97F4A7C15ull) >> 32) & mask_;  // Fibonacci hashing
  }
  size_t slotOf(uint64_t key) const {
    if (keys_.empty()) return kMissing;
    for (size_t i = home(key);; i = (i + 1) & mask_) {
      if (keys_[i] == key) return i;
      if (keys_[i] == kNoEdge) return kMissing;
    }
  }
  void rehash(size_t capacity) {
    std::vector<uint64_t> keys(capacity, kNoEdge);
    std::vector<Value> values(capacity);
    keys.swap(keys_);
    values.swap(values_);
    mask_ = capacity - 1;
    count_ = 0;
    for (size_t i = 0; i < keys.size(); ++i)
      if (keys[i] != kNoEdge) (*this)[keys[i]] = std::move(values[i]);
  }

  std::vector<uint64_t> keys_;
  std::vector<Value> values_;
  size_t count_ = 0;
  size_t mask_ = 0;
};

}  // namespace tessera
