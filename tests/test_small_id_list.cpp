// SmallIdList: a std::vector<uint32_t>'s order and contents, the first two ids inline.
#include <catch2/catch.hpp>

#include <vector>

#include "common/small_id_list.h"

using namespace tessera;

TEST_CASE("SmallIdList keeps a vector's entries in order past its two inline ones", "[mesh]") {
  SmallIdList list;
  std::vector<uint32_t> expected;
  CHECK(list.empty());
  for (uint32_t id : {7u, 3u, 7u, 9u, 1u}) {
    list.push_back(id);
    expected.push_back(id);
    REQUIRE(list.size() == expected.size());
    for (size_t k = 0; k < expected.size(); ++k) CHECK(list[k] == expected[k]);
  }
  list.replace(7, 4);  // both 7s, the inline one and the spilled one
  CHECK(list[0] == 4);
  CHECK(list[2] == 4);
  CHECK(list[1] == 3);
  list[4] = 8;
  CHECK(list[4] == 8);
  const SmallIdList copy = list;
  list.push_back(5);
  CHECK(copy.size() == 5);
  CHECK(list.size() == 6);
  const SmallIdList pair(2, 6);
  CHECK(pair.size() == 2);
  CHECK(pair[0] == 2);
  CHECK(pair[1] == 6);
}
