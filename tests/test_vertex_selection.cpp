// Vertex selections (host/io/vertex_selection.h): 1-based OBJ vertex numbers and ranges from a
// file (blanks, commas and lines between them, comments) or a command-line list; bad tokens
// name the file, line and reason with the InputError kind.
#include <catch2/catch.hpp>

#include <sstream>
#include <stdexcept>

#include "io/errors.h"
#include "io/vertex_selection.h"
#include "input_error_checks.h"

using namespace tessera;

namespace {

std::vector<uint32_t> parse(const std::string& text, uint32_t count = 10) {
  std::istringstream in(text);
  return parseVertexSelection(in, "sel.txt", count);
}

}  // namespace

TEST_CASE("Vertex selection files: numbers, ranges, commas, comments; 0-based, sorted, unique",
          "[io][loop]") {
  const std::vector<uint32_t> expected{0, 2, 3, 4, 6, 9};
  REQUIRE(parse("# chosen\n7 1\r\n3-5,10 # the tip\n\n4,\n") == expected);
  REQUIRE(parse("\xEF\xBB\xBF" "1 3,4,5 7 10") == expected);  // one line, a BOM
  REQUIRE(parse("10") == std::vector<uint32_t>{9});
}

TEST_CASE("Vertex selection files: bad tokens name the file, line and reason", "[io][loop]") {
  const auto read = [](const std::string& text, const std::string& name) {
    std::istringstream in(text);
    parseVertexSelection(in, name, 10);
  };
  test::checkBadTexts(
      {{"letter.txt", "1 2\n3 x\n", InputErrorKind::Syntax, 2, "'x' is not a vertex number"},
       {"fraction.txt", "1.5", InputErrorKind::Syntax, 1, "'1.5' is not a vertex number"},
       {"zero.txt", "1\n0\n", InputErrorKind::Range, 2, "vertex '0': OBJ vertex numbers start at 1"},
       {"negative.txt", "-3", InputErrorKind::Range, 1, "OBJ vertex numbers start at 1"},
       {"past.txt", "4\n\n2-11", InputErrorKind::Range, 3, "vertex '11' is past the mesh's 10 vertices"},
       {"huge.txt", "99999999999999999999", InputErrorKind::Range, 1, "is past the mesh's 10 vertices"},
       {"backwards.txt", "7-3", InputErrorKind::Range, 1, "the range '7-3' runs backwards"},
       {"open_range.txt", "3-", InputErrorKind::Syntax, 1, "'3-' is not a vertex number"}},
      read);
  // No line to name: "<file>: <reason>".
  const InputError empty = test::inputErrorOf([&] { read("# nothing\n", "empty.txt"); }, "empty");
  REQUIRE(empty.kind() == InputErrorKind::Count);
  REQUIRE(std::string(empty.what()) == "empty.txt: names no vertex (expected 1-based vertex numbers)");
  REQUIRE(test::inputErrorOf([] { readVertexSelection("/nonexistent/sel.txt", 10); }, "missing")
              .kind() == InputErrorKind::Io);
}

TEST_CASE("Vertex lists on the command line: the same rules, as std::invalid_argument",
          "[io][loop]") {
  REQUIRE(parseVertexList("12,15,40-42", 50) == std::vector<uint32_t>{11, 14, 39, 40, 41});
  REQUIRE_THROWS_WITH(parseVertexList("3,x", 50), Catch::Contains("'x' is not a vertex number"));
  REQUIRE_THROWS_WITH(parseVertexList("51", 50), Catch::Contains("past the mesh's 50 vertices"));
  REQUIRE_THROWS_WITH(parseVertexList(",", 50), Catch::Contains("names no vertex"));
  // The form alone, before the mesh is known: any number ≥ 1 passes.
  REQUIRE_NOTHROW(checkVertexList("1-4000000000"));
  REQUIRE_THROWS_AS(checkVertexList("0"), std::invalid_argument);
  REQUIRE_THROWS_AS(checkVertexList("5-2"), std::invalid_argument);
}
