// firstOccurrences (common/first_occurrence.h) keeps its shards' hash tables from call to call
// (TablePool): a table must come back empty, whatever size the last call left it, or an item
// would be matched with a key of an earlier call. Checked against a plain map, on one and on
// several threads, with calls of different sizes in turn.
#include <catch2/catch.hpp>

#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include "common/first_occurrence.h"

using namespace tessera;

namespace {

struct IdentityHash {
  size_t operator()(uint64_t key) const { return size_t(key); }
};

// The first index of each item's key, by a plain map.
std::vector<uint32_t> firstByMap(const std::vector<uint64_t>& keys) {
  std::map<uint64_t, uint32_t> seen;
  std::vector<uint32_t> first(keys.size());
  for (size_t i = 0; i < keys.size(); ++i) first[i] = seen.emplace(keys[i], uint32_t(i)).first->second;
  return first;
}

std::vector<uint32_t> firstByTables(const std::vector<uint64_t>& keys, unsigned threads) {
  const auto forEachKey = [&](auto&& visit) {
    for (size_t i = 0; i < keys.size(); ++i) visit(i, keys[i]);
  };
  return firstOccurrences<uint64_t, IdentityHash>(keys.size(), keys.size() / 2, forEachKey,
                                                  threads);
}

// `count` keys drawn from `distinct` values of a range that starts at `offset`.
std::vector<uint64_t> randomKeys(size_t count, uint64_t distinct, uint64_t offset, unsigned seed) {
  std::mt19937_64 random(seed);
  std::vector<uint64_t> keys(count);
  for (uint64_t& key : keys) key = offset + random() % distinct;
  return keys;
}

}  // namespace

TEST_CASE("firstOccurrences: the first item of each key, call after call", "[first_occurrence]") {
  // Large, small, large again and a small one of the same keys in another order: a table
  // that kept an earlier call's keys would answer with that call's indices.
  const std::vector<std::vector<uint64_t>> calls = {
      randomKeys(40000, 15000, 0, 1), randomKeys(300, 100, 0, 2), randomKeys(50000, 30000, 7, 3),
      randomKeys(9000, 4000, 0, 4), randomKeys(9000, 4000, 0, 5), {}};
  for (unsigned threads : {1u, 2u, 3u}) {
    for (size_t c = 0; c < calls.size(); ++c) {
      INFO("threads " << threads << ", call " << c);
      const std::vector<uint32_t> expected = firstByMap(calls[c]);
      REQUIRE(firstByTables(calls[c], threads) == expected);
    }
  }
}
