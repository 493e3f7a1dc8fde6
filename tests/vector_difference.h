// Equality of two long vectors (a mesh's indices or positions) told in one line. Catch2 prints
// both sides of a failed `REQUIRE(a == b)`, and its console reporter took minutes to wrap two
// index arrays of 10^5 numbers (a GPU test on an H100 ran into its time limit doing it).
//   REQUIRE(test::vectorDifference(a, b) == "");
#pragma once
#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

namespace tessera::test {

// "" when equal; else the sizes, how many elements differ and the first difference.
template <class T>
std::string vectorDifference(const std::vector<T>& a, const std::vector<T>& b) {
  const size_t common = std::min(a.size(), b.size());
  size_t differing = 0, first = common;
  for (size_t i = 0; i < common; ++i)
    if (!(a[i] == b[i])) {
      if (differing++ == 0) first = i;
    }
  if (differing == 0 && a.size() == b.size()) return "";
  std::ostringstream text;
  text << "sizes " << a.size() << " and " << b.size() << ", " << differing << " of the first "
       << common << " differ";
  if (first < common)
    text << ", first at " << first << ": " << Catch::Detail::stringify(a[first]) << " against "
         << Catch::Detail::stringify(b[first]);
  return text.str();
}

}  // namespace tessera::test
