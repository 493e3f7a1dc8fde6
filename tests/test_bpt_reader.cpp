// The .bpt reader (host/io/bpt_reader.h): the bundled tea set reads as published, and every
// kind of malformed file is rejected with the right error kind, file name, line and reason.
#include <catch2/catch.hpp>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "input_error_checks.h"
#include "io/bpt_reader.h"
#include "io/errors.h"
#include "scratch_dir.h"

using namespace tessera;

namespace {

std::vector<BezierPatch> parse(const std::string& text) {
  std::istringstream in(text);
  return parseBpt(in, "test.bpt");
}

// The InputError parsing `text` throws; fails the test if it throws none.
InputError parseError(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  return test::inputErrorOf([&] { parseBpt(in, name); }, name);
}

// A valid bilinear patch: a degree line and 4 point lines.
const std::string kBilinear = "1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n";

void checkAllWellFormed(const std::vector<BezierPatch>& patches) {
  for (const BezierPatch& p : patches) {
    CHECK(p.degreeU >= 1);
    CHECK(p.degreeU <= kMaxDegree);
    CHECK(p.degreeV >= 1);
    CHECK(p.degreeV <= kMaxDegree);
    CHECK(p.cp.size() == size_t((p.degreeU + 1) * (p.degreeV + 1)));
  }
}

}  // namespace

TEST_CASE("bpt: the bundled teapot is 32 bicubic patches", "[io][bpt]") {
  const auto patches = readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt");
  REQUIRE(patches.size() == 32);
  for (const BezierPatch& p : patches) {
    CHECK(p.degreeU == 3);
    CHECK(p.degreeV == 3);
    CHECK(p.cp.size() == 16);
  }
  // First and last lines of the first patch in the file; from_chars rounds correctly, so the
  // values equal the literals exactly.
  CHECK(patches[0].cp[0] == glm::dvec3(1.4, 0.0, 2.4));
  CHECK(patches[0].at(0, 1) == glm::dvec3(1.4, -0.784, 2.4));
  CHECK(patches[0].at(3, 3) == glm::dvec3(0.0, -1.5, 2.4));
}

TEST_CASE("bpt: the bundled teacup and teaspoon", "[io][bpt]") {
  const auto teacup = readBpt(TESSERA_SOURCE_DIR "/data/teacup.bpt");
  CHECK(teacup.size() == 26);
  checkAllWellFormed(teacup);
  const auto teaspoon = readBpt(TESSERA_SOURCE_DIR "/data/teaspoon.bpt");
  CHECK(teaspoon.size() == 16);
  checkAllWellFormed(teaspoon);
}

TEST_CASE("bpt: control points are row by row, i along u", "[io][bpt]") {
  // Degrees (1, 2): two rows of three points; b_ij = (i, j, 10 i + j).
  const auto patches = parse("1\n1 2\n0 0 0\n0 1 1\n0 2 2\n1 0 10\n1 1 11\n1 2 12\n");
  REQUIRE(patches.size() == 1);
  const BezierPatch& p = patches[0];
  CHECK(p.degreeU == 1);
  CHECK(p.degreeV == 2);
  for (int i = 0; i <= 1; ++i)
    for (int j = 0; j <= 2; ++j) CHECK(p.at(i, j) == glm::dvec3(i, j, 10 * i + j));
}

TEST_CASE("bpt: comments, blank lines, CRLF and number spellings", "[io][bpt]") {
  const std::string text =
      "# a comment before the count\r\n"
      "\r\n"
      "  2  \r\n"
      "\t# indented comment\n" +
      kBilinear +
      "\n"
      "1 1\n"
      "+1.5 -2.5e-3 .25\n"
      "1. 1E2 -0\n"
      "\n"
      "# between points\n"
      "7 8 9\n"
      "1e15 -1e15 0.0\n"
      "\n   \n# trailing comment\n";
  const auto patches = parse(text);
  REQUIRE(patches.size() == 2);
  CHECK(patches[0].at(1, 1) == glm::dvec3(1, 1, 0));
  CHECK(patches[1].cp[0] == glm::dvec3(1.5, -2.5e-3, 0.25));
  CHECK(patches[1].cp[1] == glm::dvec3(1.0, 100.0, 0.0));
  CHECK(patches[1].cp[2] == glm::dvec3(7, 8, 9));
  CHECK(patches[1].cp[3] == glm::dvec3(1e15, -1e15, 0));
}

TEST_CASE("bpt: malformed files name the error kind, file, line and reason", "[io][bpt]") {
  const std::vector<test::BadTextCase> cases = {
      {"empty.bpt", "", InputErrorKind::Count, 1, "empty file: expected the patch count"},
      {"only_comments.bpt", "# nothing here\n\n", InputErrorKind::Count, 3, "empty file"},
      {"truncated_in_patch.bpt", "1\n1 1\n0 0 0\n1 0 0\n", InputErrorKind::Count, 5,
       "file ends early: expected control point 3 of 4 of patch 1 of 1"},
      {"truncated_no_newline.bpt", "1\n1 1\n0 0 0\n1 0 0", InputErrorKind::Count, 5,
       "expected control point 3 of 4"},
      {"truncated_before_patch.bpt", "2\n" + kBilinear, InputErrorKind::Count, 7,
       "file ends early: expected the degrees \"n m\" of patch 2 of 2"},
      {"count_too_small.bpt", "1\n" + kBilinear + kBilinear, InputErrorKind::Count, 7,
       "more patches than the 1 declared on line 1"},
      {"count_zero.bpt", "0\n", InputErrorKind::Count, 1, "patch count must be at least 1, found 0"},
      {"count_negative.bpt", "\n-3\n", InputErrorKind::Count, 2, "at least 1, found -3"},
      {"count_huge.bpt", "99999999999999999999999\n", InputErrorKind::Count, 1, "is too large"},
      {"count_word.bpt", "two\n" + kBilinear, InputErrorKind::Syntax, 1,
       "'two' is not an integer patch count"},
      {"count_extra.bpt", "1 patch\n" + kBilinear, InputErrorKind::Syntax, 1,
       "expected the patch count (one integer), found 2 tokens"},
      {"not_a_number.bpt", "1\n1 1\n0 0 0\n1 zero 0\n0 1 0\n1 1 0\n", InputErrorKind::Syntax, 4,
       "'zero' is not a number (y of control point 2 of 4 of patch 1 of 1)"},
      {"decimal_comma.bpt", "1\n1 1\n0 0 0\n1,5 0 0\n0 1 0\n1 1 0\n", InputErrorKind::Syntax, 4,
       "'1,5' is not a number (x of control point 2"},
      {"hex_float.bpt", "1\n1 1\n0x1p3 0 0\n1 0 0\n0 1 0\n1 1 0\n", InputErrorKind::Syntax, 3,
       "'0x1p3' is not a number"},
      {"nan.bpt", "1\n1 1\nnan 0 0\n1 0 0\n0 1 0\n1 1 0\n", InputErrorKind::NonFinite, 3,
       "'nan' is not a finite number (x of control point 1 of 4 of patch 1 of 1)"},
      {"inf.bpt", "1\n1 1\n0 0 0\n1 0 0\n0 1 -inf\n1 1 0\n", InputErrorKind::NonFinite, 5,
       "'-inf' is not a finite number (z of control point 3 of 4"},
      {"huge.bpt", "1\n1 1\n0 0 0\n1 0 0\n0 1e300 0\n1 1 0\n", InputErrorKind::Range, 5,
       "'1e300' exceeds the largest accepted magnitude 1e15 (y of control point 3 of 4"},
      {"just_over.bpt", "1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 -1.0000001e15\n", InputErrorKind::Range,
       6, "exceeds the largest accepted magnitude"},
      {"overflow.bpt", "1\n1 1\n0 0 0\n1e400 0 0\n0 1 0\n1 1 0\n", InputErrorKind::Range, 4,
       "'1e400' is outside the range of a double"},
      {"degree_zero.bpt", "1\n0 1\n0 0 0\n1 0 0\n", InputErrorKind::Degree, 2,
       "degree in u of patch 1 of 1 is 0; must be 1..7"},
      {"degree_eight.bpt", "1\n3 8\n", InputErrorKind::Degree, 2,
       "degree in v of patch 1 of 1 is 8; must be 1..7"},
      {"degree_second_patch.bpt", "2\n" + kBilinear + "# next\n1 -1\n", InputErrorKind::Degree, 8,
       "degree in v of patch 2 of 2 is -1"},
      {"degree_real.bpt", "1\n3.0 3\n", InputErrorKind::Syntax, 2,
       "'3.0' is not an integer degree (u of patch 1 of 1)"},
      {"degree_one_token.bpt", "1\n3\n", InputErrorKind::Syntax, 2,
       "expected the degrees \"n m\" of patch 1 of 1 (two integers), found 1 tokens"},
      {"extra_token.bpt", "1\n1 1\n0 0 0\n1 0 0 0\n0 1 0\n1 1 0\n", InputErrorKind::Syntax, 4,
       "expected 3 numbers \"x y z\" for control point 2 of 4 of patch 1 of 1, found 4 tokens"},
      {"missing_token.bpt", "1\n1 1\n0 0 0\n1 0\n0 1 0\n1 1 0\n", InputErrorKind::Syntax, 4,
       "found 2 tokens"},
      {"trailing_comment.bpt", "1\n1 1\n0 0 0 # origin\n1 0 0\n0 1 0\n1 1 0\n",
       InputErrorKind::Syntax, 3, "'#' starts a comment only at the beginning of a line"},
      {"short_patch.bpt", "2\n1 1\n0 0 0\n1 0 0\n0 1 0\n" + kBilinear, InputErrorKind::Syntax, 6,
       "(a degree line? patch 1 of 2 needs 4 control points)"},
      {"long_patch.bpt", "2\n" + kBilinear + "2 2 2\n" + kBilinear, InputErrorKind::Syntax, 7,
       "patch 1 may have more points than its degrees allow"},
      {"trailing_garbage.bpt", "1\n" + kBilinear + "\nend\n", InputErrorKind::Syntax, 8,
       "unexpected content 'end' after the last of the 1 declared on line 1"},
  };

  for (const test::BadTextCase& c : cases) {
    INFO("case " << c.name);
    const InputError e = parseError(c.text, c.name);
    test::checkInputError(e, c.name, c.kind, c.line, c.reason);
    CHECK(e.reason().find(c.reason) != std::string::npos);  // in the reason, not the prefix
  }
}

TEST_CASE("bpt: readBpt names the path in its errors", "[io][bpt]") {
  test::ScratchDir dir("bpt");
  SECTION("a malformed file on disk") {
    const std::string path = (dir.path / "bad.bpt").string();
    std::ofstream(path) << "1\n1 1\n0 0 0\n";
    try {
      readBpt(path);
      FAIL("no error");
    } catch (const InputError& e) {
      CHECK(e.kind() == InputErrorKind::Count);
      CHECK(e.file() == path);
      CHECK(std::string(e.what()) == path + ":4: file ends early: expected control point 2 of 4 of patch 1 of 1 (\"x y z\")");
    }
  }
  SECTION("a missing file") {
    const std::string path = (dir.path / "missing.bpt").string();
    try {
      readBpt(path);
      FAIL("no error");
    } catch (const InputError& e) {
      CHECK(e.kind() == InputErrorKind::Io);
      CHECK(e.line() == 0);
      CHECK(std::string(e.what()) == path + ": cannot open for reading: No such file or directory");
    }
  }
  SECTION("a directory") {
    try {
      readBpt(dir.path.string());
      FAIL("no error");
    } catch (const InputError& e) {
      CHECK(e.kind() == InputErrorKind::Io);
      CHECK(std::string(e.what()).find("is a directory") != std::string::npos);
    }
  }
}

TEST_CASE("bpt: InputError formats like a compiler message", "[io][errors]") {
  const InputError withLine(InputErrorKind::Syntax, "scene.json", 12, "expected ']'");
  CHECK(std::string(withLine.what()) == "scene.json:12: expected ']'");
  CHECK(withLine.reason() == "expected ']'");
  const InputError noLine(InputErrorKind::Io, "out/mesh.obj", 0, "cannot write");
  CHECK(std::string(noLine.what()) == "out/mesh.obj: cannot write");
  CHECK(std::string(inputErrorKindName(InputErrorKind::Knots)) == "Knots");
}
