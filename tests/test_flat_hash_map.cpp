// FlatHashMap (common/flat_hash_map.h) against std::unordered_map on random keys: the same
// values found, the first value kept for a key inserted twice, through several growths of the
// table, and with a hash that sends every key to one slot (the probing alone finds them).
#include <catch2/catch.hpp>

#include <random>
#include <unordered_map>

#include "common/flat_hash_map.h"

using namespace tessera;

namespace {

struct PlainHash {
  size_t operator()(uint64_t k) const { return size_t(k); }
};

struct OneSlotHash {
  size_t operator()(uint64_t) const { return 7; }
};

template <class Hash>
void checkAgainstStd(size_t count, uint64_t keyRange, size_t expected) {
  std::mt19937_64 random(20261127);
  std::uniform_int_distribution<uint64_t> keyOf(0, keyRange);
  FlatHashMap<uint64_t, uint32_t, Hash> flat(expected);
  std::unordered_map<uint64_t, uint32_t> reference;
  for (uint32_t i = 0; i < count; ++i) {
    const uint64_t key = keyOf(random);
    const auto [value, inserted] = flat.tryEmplace(key, i);
    const auto [it, stdInserted] = reference.emplace(key, i);
    REQUIRE(inserted == stdInserted);
    REQUIRE(*value == it->second);
  }
  REQUIRE(flat.size() == reference.size());
  for (uint64_t key = 0; key <= std::min<uint64_t>(keyRange, 4 * count); ++key) {
    const uint32_t* found = flat.find(key);
    const auto it = reference.find(key);
    REQUIRE((found != nullptr) == (it != reference.end()));
    if (found) REQUIRE(*found == it->second);
  }
}

}  // namespace

TEST_CASE("flat hash map: finds what std::unordered_map finds", "[flat_hash_map]") {
  checkAgainstStd<PlainHash>(20000, 30000, 0);      // repeats, grown from 16 slots
  checkAgainstStd<PlainHash>(20000, 1ull << 62, 20000);  // sized up front, spread keys
  checkAgainstStd<OneSlotHash>(500, 800, 0);        // every key probes from one slot
  FlatHashMap<uint64_t, uint32_t, PlainHash> empty;
  REQUIRE(empty.empty());
  REQUIRE(empty.find(3) == nullptr);
}
