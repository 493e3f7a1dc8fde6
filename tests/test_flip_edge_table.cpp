// FlipEdgeTable (trim/detail/flip_edge_table.h): the gap flips' edge → triangles table must
// answer as a std::map does through inserts, erases (the backward shift moves entries across
// the array's end, their `fixed` flag with them) and lookups, and a second table on the thread
// must start empty.
#include <catch2/catch.hpp>

#include <map>
#include <random>
#include <vector>

#include "trim/detail/flip_edge_table.h"

using tessera::SmallIdList;
using tessera::trim_detail::FlipEdgeTable;

namespace {

std::vector<uint32_t> idsOf(const SmallIdList& list) {
  std::vector<uint32_t> ids;
  for (size_t k = 0; k < list.size(); ++k) ids.push_back(list[k]);
  return ids;
}

}  // namespace

TEST_CASE("flip edge table: the same answers as a std::map under random edits",
          "[gap][flip_table]") {
  std::mt19937_64 rng(23);
  for (size_t triangles : {1u, 3u, 20u, 200u}) {
    FlipEdgeTable table(triangles);
    std::map<uint64_t, std::vector<uint32_t>> reference;
    std::map<uint64_t, bool> fixed;  // the keys marked fixed, while present
    // Few distinct vertices: keys collide on their home slots and clusters wrap around.
    std::uniform_int_distribution<uint32_t> vertex(0, uint32_t(2 + triangles));
    const auto randomKey = [&] {
      uint32_t a = vertex(rng), b = vertex(rng);
      if (a > b) std::swap(a, b);
      return uint64_t(a) << 32 | b;
    };
    for (int step = 0; step < 20000; ++step) {
      const uint64_t key = randomKey();
      const int action = int(rng() % 4);
      if (action == 0 && reference.size() < 3 * triangles) {
        const uint32_t id = uint32_t(rng() % 1000);
        table[key].ids.push_back(id);
        reference[key].push_back(id);
      } else if (action == 1) {
        table.erase(key);
        reference.erase(key);
        fixed.erase(key);
      } else if (action == 2 && reference.count(key)) {
        const uint32_t to = uint32_t(rng() % 1000);
        const uint32_t from = reference[key][0];
        table[key].ids.replace(from, to);
        for (uint32_t& id : reference[key])
          if (id == from) id = to;
      } else if (action == 3 && reference.count(key)) {
        table[key].fixed = true;
        fixed[key] = true;
      }
      const FlipEdgeTable::Entry* found = table.find(key);
      const auto expected = reference.find(key);
      REQUIRE((found != nullptr) == (expected != reference.end()));
      if (found) REQUIRE(idsOf(found->ids) == expected->second);
      if (found) REQUIRE(found->fixed == (fixed.count(key) > 0));
    }
    std::map<uint64_t, std::vector<uint32_t>> walked;
    std::map<uint64_t, bool> walkedFixed;
    table.forEach([&](uint64_t key, const FlipEdgeTable::Entry& e) {
      walked[key] = idsOf(e.ids);
      if (e.fixed) walkedFixed[key] = true;
    });
    REQUIRE(walked == reference);
    REQUIRE(walkedFixed == fixed);
  }
  // The next table on the thread reuses the slots, empty.
  FlipEdgeTable fresh(5);
  size_t entries = 0;
  fresh.forEach([&](uint64_t, const FlipEdgeTable::Entry&) { ++entries; });
  REQUIRE(entries == 0);
  REQUIRE(fresh.find(1) == nullptr);
}
