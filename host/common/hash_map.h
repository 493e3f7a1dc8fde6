// The hash maps of the mesh stages, which look up a key once per vertex, triangle or edge:
// tsl::robin_map (Debian robin-map-dev, header only): one flat array, robin-hood probing,
// erase by backward shift, no node per entry. std::unordered_map allocated a node per entry
// and followed a pointer per probe; malloc was a third of the gap triangulation's time and the
// node-based maps a quarter of rule T's stages after the tree (bench/HISTORY.md). Its iteration
// order is its own: callers that walk a map sort what they walk.
#pragma once

#include <tsl/robin_map.h>
#include <tsl/robin_set.h>

#include <cstddef>
#include <cstdint>
#include <functional>

namespace tessera {

// tsl's power-of-two tables keep a hash's low bits, and the keys here (bit patterns of floats,
// packed vertex ids) hold their entropy elsewhere: the caller's hash goes through a Fibonacci
// multiply, whose high half is folded down.
template <class Key, class Hash>
struct MixedHash {
  size_t operator()(const Key& key) const {
    const uint64_t x = uint64_t(Hash{}(key)) * 0x9E3779B97F4A7C15ull;
    return size_t(x ^ (x >> 32));
  }
};

template <class Key, class Value, class Hash = std::hash<Key>>
using HashMap = tsl::robin_map<Key, Value, MixedHash<Key, Hash>>;

template <class Key, class Hash = std::hash<Key>>
using HashSet = tsl::robin_set<Key, MixedHash<Key, Hash>>;

}  // namespace tessera
