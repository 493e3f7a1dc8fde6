// The text readers (.bpt, .grid, OBJ) read what editors on every system write (issue 18): a
// UTF-8 byte order mark, LF, CRLF and lone-CR line endings give the same data as the plain
// file, errors in a CR-only file name the right line, and formats are chosen by extension
// case-insensitively.
#include <catch2/catch.hpp>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "input_error_checks.h"
#include "io/bpt_reader.h"
#include "io/grid_reader.h"
#include "io/obj_reader.h"
#include "io/surface_reader.h"
#include "io/text_lines.h"

using namespace tessera;

namespace {

std::string fileText(const std::string& relative) {
  std::ifstream in(std::string(TESSERA_SOURCE_DIR) + "/" + relative, std::ios::binary);
  REQUIRE(in);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string replaced(std::string text, const std::string& lineEnd) {
  std::string out;
  for (char c : text)
    if (c == '\n') out += lineEnd;
    else out += c;
  return out;
}

// The variants of a text file that must read as the file itself.
std::vector<std::pair<std::string, std::string>> variants(const std::string& text) {
  return {{"BOM", std::string(kUtf8Bom) + text},
          {"CRLF", replaced(text, "\r\n")},
          {"CR only", replaced(text, "\r")},
          {"BOM and CR only", std::string(kUtf8Bom) + replaced(text, "\r")}};
}

// Every double of `a` equals `b`'s bit for bit; prints the first difference.
void requireSameDoubles(const std::vector<double>& a, const std::vector<double>& b) {
  REQUIRE(a.size() == b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    INFO("value " << i << ": " << a[i] << " vs " << b[i]);
    REQUIRE(std::memcmp(&a[i], &b[i], sizeof(double)) == 0);
  }
}

std::vector<double> flatBpt(const std::string& text) {
  std::istringstream in(text);
  std::vector<double> values;
  for (const BezierPatch& p : parseBpt(in, "test.bpt")) {
    values.push_back(p.degreeU);
    values.push_back(p.degreeV);
    for (const auto& c : p.cp) values.insert(values.end(), {c.x, c.y, c.z});
  }
  return values;
}

std::vector<double> flatGrid(const std::string& text) {
  std::istringstream in(text);
  const GridData g = parseGrid(in, "test.grid");
  std::vector<double> values{double(g.rows), double(g.cols)};
  for (const auto& c : g.points) values.insert(values.end(), {c.x, c.y, c.z});
  return values;
}

std::vector<double> flatObj(const std::string& text) {
  std::istringstream in(text);
  const PolygonMesh m = parseObj(in, "test.obj");
  std::vector<double> values;
  for (const auto& c : m.positions) values.insert(values.end(), {c.x, c.y, c.z});
  for (const auto& f : m.faces) {
    values.push_back(-1.0);
    for (uint32_t v : f) values.push_back(v);
  }
  for (int line : m.faceLines) values.push_back(line);  // CR-only lines are counted too
  return values;
}

}  // namespace

TEST_CASE("Text readers take a byte order mark and CRLF or CR-only line endings",
          "[io][bad-inputs]") {
  const struct {
    const char* file;
    std::function<std::vector<double>(const std::string&)> read;
  } formats[] = {{"data/teacup.bpt", flatBpt},
                 {"data/grid_hill.grid", flatGrid},
                 {"data/loop/ball.obj", flatObj}};
  for (const auto& format : formats) {
    const std::string text = fileText(format.file);
    const std::vector<double> plain = format.read(text);
    REQUIRE(plain.size() > 10);
    for (const auto& [name, variant] : variants(text)) {
      INFO(format.file << " with " << name);
      requireSameDoubles(format.read(variant), plain);
    }
  }
}

TEST_CASE("An error in a CR-only file names its line", "[io][bad-inputs]") {
  // Line 4 holds 2 of the 3 coordinates. With CR read as a blank the whole file was one line,
  // and the message said "expected the patch count (one integer), found 13 tokens".
  const std::string text = "1\r1 1\r0 0 0\r0 0\r0 0 0\r0 0 0\r";
  std::istringstream in(text);
  const InputError e = test::inputErrorOf([&] { parseBpt(in, "cr.bpt"); }, "cr.bpt");
  test::checkInputError(e, "cr.bpt", InputErrorKind::Syntax, 4,
                        "expected 3 numbers \"x y z\" for control point 2 of 4 of patch 1 of 1, "
                        "found 2 tokens");
}

TEST_CASE("Surface formats are chosen by extension whatever its case", "[io]") {
  CHECK(formatOfExtension("a/teapot.BPT") == "bpt");
  CHECK(formatOfExtension("Hill.Grid") == "grid");
  CHECK(formatOfExtension("scene.JSON") == "json");
  CHECK(formatOfExtension("noextension") == "");
  const std::filesystem::path copy = std::filesystem::temp_directory_path() /
                                     ("tessera_test_TEACUP_" + std::to_string(::getpid()) + ".BPT");
  std::filesystem::copy_file(std::string(TESSERA_SOURCE_DIR) + "/data/teacup.bpt", copy,
                             std::filesystem::copy_options::overwrite_existing);
  const auto upper = readSurfaceFile(copy.string());
  std::filesystem::remove(copy);
  const auto lower = readSurfaceFile(std::string(TESSERA_SOURCE_DIR) + "/data/teacup.bpt");
  REQUIRE(upper.size() == lower.size());
  for (size_t p = 0; p < upper.size(); ++p) REQUIRE(upper[p].cp == lower[p].cp);
}
