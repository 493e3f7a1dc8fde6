// The triangulator's line index (host/mesh/line_index.h): lines numbered in the order they are
// first met, whatever is looked up in between. Near-point merges walk the lines in an order
// derived from these numbers (LineIndex::unorderedMapOrder), and merges hand out the ids that
// meshes keep, so the numbering is a contract.
#include <catch2/catch.hpp>

#include "mesh/detail/run_places.h"
#include "mesh/line_index.h"

using namespace tessera;

TEST_CASE("line index: lines numbered in the order first met", "[triangulate]") {
  LineIndex index(4);
  const uint64_t keys[] = {7ull << 32 | 5, 3, 7ull << 32 | 2, 1ull << 40};
  for (size_t k = 0; k < 4; ++k) {
    REQUIRE(index.number(keys[k]) == k);
    // Met again (a leaf's second corner on it): the same number, no new line.
    REQUIRE(index.number(keys[0]) == 0);
    REQUIRE(index.number(keys[k]) == k);
    REQUIRE(index.size() == k + 1);
  }
  // Growing past the size asked for keeps the numbers.
  for (uint64_t k = 0; k < 1000; ++k) index.number(1000 + k);
  for (size_t k = 0; k < 4; ++k) REQUIRE(index.number(keys[k]) == k);
  REQUIRE(index.size() == 1004);
  for (size_t line = 0; line < index.size(); ++line)
    REQUIRE(index.key(line) == (line < 4 ? keys[line] : 1000 + (line - 4)));
  // Points go in the room allocated for their line; the lines share one array.
  std::vector<uint32_t> room(index.size(), 0);
  room[2] = 2;
  room[3] = 1;
  index.allocatePoints(room);
  index.add(index.number(keys[2]), {0.5f, 0.25f});
  index.add(3, {0.75f, 0.5f});
  REQUIRE(index.points(2).size() == 1);
  REQUIRE(index.points(2)[0].t == 0.5f);
  REQUIRE(index.points(3).size() == 1);
  REQUIRE(index.points(3)[0].t == 0.75f);
  REQUIRE(index.points(1).empty());
  REQUIRE(index.points(index.number(99)).empty());  // numbered after the room was given
  index.add(index.number(keys[2]), {0.25f, 0.25f});
  REQUIRE(index.points(2).size() == 2);
  index.shrink(2, 1);
  REQUIRE(index.points(2).size() == 1);
  REQUIRE(index.points(3)[0].t == 0.75f);  // the neighbour's room untouched
}

TEST_CASE("line index: the merge walk order is std::unordered_map's", "[triangulate]") {
  LineIndex index(8);
  std::unordered_map<uint64_t, uint32_t> expected;
  expected.reserve(16);
  for (uint64_t k = 0; k < 200; ++k) {
    const uint64_t key = (k % 7) << 32 | (k * 2654435761u) % 1000;
    const uint32_t line = index.number(key);
    expected.emplace(key, line);
  }
  std::vector<uint32_t> lines;
  for (const auto& entry : expected) lines.push_back(entry.second);
  REQUIRE(index.unorderedMapOrder(16) == lines);
}

// A leaf corner met again right after on its line (the next leaf's) folds into the last point,
// keeping the shorter spacing; the same t further back, or −0 after +0, stays a point of its own
// (nearPairs folds those after sorting).
TEST_CASE("line index: a repeat of the last point folds into it", "[triangulate]") {
  LineIndex index(1);
  REQUIRE(index.number(5) == 0);
  index.allocatePoints({5});
  index.addOrFold(0, {0.5f, 0.25f});
  index.addOrFold(0, {0.5f, 0.125f});
  REQUIRE(index.points(0).size() == 1);
  REQUIRE(index.points(0)[0].spacing == 0.125f);
  index.addOrFold(0, {0.5f, 0.5f});
  REQUIRE(index.points(0)[0].spacing == 0.125f);
  index.addOrFold(0, {0.75f, 0.25f});
  index.addOrFold(0, {0.5f, 0.25f});
  index.addOrFold(0, {0.0f, 0.25f});
  index.addOrFold(0, {-0.0f, 0.25f});
  REQUIRE(index.points(0).size() == 5);
}

// The leaf walk's key → place table (mesh/detail/run_places.h), past the size it was made for:
// every key keeps the place it was first given, whatever its kind, however the table grew.
TEST_CASE("run places: a key keeps its first place as the table grows", "[triangulate]") {
  using namespace tessera::triangulate_detail;
  RunPlaces places(4);
  const auto keyOf = [](uint32_t k) {
    return VertexKey{k % 4, k / 3, uint64_t(k) * 0x10001ull};
  };
  for (uint32_t k = 0; k < 3000; ++k) {
    bool added = false;
    REQUIRE(places.findOrAdd(keyOf(k), k, added) == k);
    REQUIRE(added);
    // Asked again with another place: the first one, nothing added.
    REQUIRE(places.findOrAdd(keyOf(k), 99999, added) == k);
    REQUIRE_FALSE(added);
  }
  for (uint32_t k = 0; k < 3000; ++k) {
    bool added = true;
    REQUIRE(places.findOrAdd(keyOf(k), 99999, added) == k);
    REQUIRE_FALSE(added);
  }
  // Reset for the next run (its slots kept, or fewer where far too many): empty again.
  for (size_t keys : {size_t(2000), size_t(10)}) {
    places.reset(keys);
    REQUIRE(places.slotCount() >= 2 * keys + 2);
    REQUIRE(places.slotCount() <= 8 * keys + 64);
    bool added = false;
    REQUIRE(places.findOrAdd(keyOf(7), 3, added) == 3);
    REQUIRE(added);
  }
}
