// An insert-and-find hash map in one array (open addressing, linear probing, a power-of-two
// table at most half full), for the mesh stages' lookups that run once per vertex or triangle.
// std::unordered_map allocates a node per entry (and, through emplace, one per lookup of a key
// that is already there) and follows a pointer per probe; here a lookup is a hash and, most
// often, one slot. No erase, no iteration: where a caller needs an order, it keeps one itself.
// (edge_hash_map.h is the same scheme for 64-bit edge keys, with erase: trim's per-face maps.)
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace tessera {

template <class Key, class Value, class Hash>
class FlatHashMap {
 public:
  explicit FlatHashMap(size_t expected = 0) { reserve(expected); }

  // Room for `expected` entries without growing.
  void reserve(size_t expected) {
    size_t capacity = 16;
    while (capacity < 2 * expected) capacity *= 2;
    if (capacity > slots_.size()) rehash(capacity);
  }

  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

  // The value stored for `key`, or null.
  const Value* find(const Key& key) const {
    for (size_t i = home(key);; i = (i + 1) & mask_) {
      const Slot& s = slots_[i];
      if (!s.used) return nullptr;
      if (s.key == key) return &s.value;
    }
  }
  Value* find(const Key& key) {
    return const_cast<Value*>(static_cast<const FlatHashMap&>(*this).find(key));
  }

  // Asks the cache for the slot where a lookup of `key` starts: a caller that knows its next
  // keys ahead overlaps their memory latency (the tables are larger than a core's cache).
  void prefetch(const Key& key) const { __builtin_prefetch(&slots_[home(key)]); }

  // Stores (key, value) unless `key` is there already; returns the stored value (the new one
  // or the one found) and whether it was inserted. The pointer lasts until the next insertion.
  std::pair<Value*, bool> tryEmplace(const Key& key, const Value& value) {
    if (2 * (size_ + 1) > slots_.size()) rehash(2 * slots_.size());
    for (size_t i = home(key);; i = (i + 1) & mask_) {
      Slot& s = slots_[i];
      if (!s.used) {
        s = {key, value, true};
        ++size_;
        return {&s.value, true};
      }
      if (s.key == key) return {&s.value, false};
    }
  }

 private:
  struct Slot {
    Key key;
    Value value;
    bool used;
  };

  // The caller's hash, mixed (Fibonacci hashing): hashes such as a bit pattern or a product of
  // indices keep their entropy in bits that a power-of-two mask would drop.
  size_t home(const Key& key) const {
    return size_t((uint64_t(Hash{}(key)) * 0x9E3779B97F4A7C15ull) >> shift_);
  }

  void rehash(size_t capacity) {
    std::vector<Slot> old(capacity, Slot{Key{}, Value{}, false});
    old.swap(slots_);
    mask_ = capacity - 1;
    shift_ = 64;
    for (size_t c = capacity; c > 1; c /= 2) --shift_;
    size_ = 0;
    for (const Slot& s : old)
      if (s.used) tryEmplace(s.key, s.value);
  }

  std::vector<Slot> slots_;
  size_t size_ = 0;
  size_t mask_ = 0;
  int shift_ = 64;
};

}  // namespace tessera
