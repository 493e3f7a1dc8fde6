// EdgeHashMap against std::unordered_map: the same entries after random inserts, updates and
// erases (erase by backward shift must keep every other key findable), through growth.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <unordered_map>
#include <vector>

#include "common/edge_hash_map.h"

using namespace tessera;

TEST_CASE("EdgeHashMap keeps std::unordered_map's entries through inserts and erases", "[mesh]") {
  std::mt19937 rng(4242);
  // Few distinct vertices, so keys collide in the table and erases shift runs back.
  std::uniform_int_distribution<uint32_t> vertex(0, 60);
  std::uniform_int_distribution<int> action(0, 9);
  EdgeHashMap<int> map;
  std::unordered_map<uint64_t, int> expected;
  for (int step = 0; step < 20000; ++step) {
    const uint32_t a = vertex(rng), b = vertex(rng);
    const uint64_t key = uint64_t(std::min(a, b)) << 32 | std::max(a, b);
    const int what = action(rng);
    if (what < 5) {
      map[key] += step;
      expected[key] += step;
    } else if (what < 8) {
      map.erase(key);
      expected.erase(key);
    } else {
      const int* found = map.find(key);
      const auto it = expected.find(key);
      REQUIRE((found != nullptr) == (it != expected.end()));
      if (found) REQUIRE(*found == it->second);
    }
    REQUIRE(map.size() == expected.size());
  }
  std::vector<std::pair<uint64_t, int>> entries;
  map.forEach([&](uint64_t key, int value) { entries.push_back({key, value}); });
  std::vector<std::pair<uint64_t, int>> wanted(expected.begin(), expected.end());
  std::sort(entries.begin(), entries.end());
  std::sort(wanted.begin(), wanted.end());
  CHECK(entries == wanted);
  CHECK(map.contains(wanted.front().first));
  map.erase(wanted.front().first);
  CHECK_FALSE(map.contains(wanted.front().first));
}
