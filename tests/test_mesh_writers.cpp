// TriangleMesh::validate and the OBJ / PLY writers (host/mesh/mesh.h, host/io/obj_writer.h,
// host/io/ply_writer.h): OBJ parses back to the same floats, PLY has exactly the header and
// byte size its layout promises.
#include <catch2/catch.hpp>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "io/errors.h"
#include "io/obj_writer.h"
#include "io/ply_writer.h"
#include "mesh/mesh.h"
#include "scratch_dir.h"

using namespace tessera;
namespace fs = std::filesystem;
using test::ScratchDir;

namespace {

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) result.push_back(line);
  return result;
}

size_t countPrefix(const std::vector<std::string>& all, const std::string& prefix) {
  return size_t(std::count_if(all.begin(), all.end(),
                              [&](const std::string& l) { return l.rfind(prefix, 0) == 0; }));
}

std::vector<float> floatsAfterTag(const std::string& line) {
  std::vector<float> values;
  std::istringstream in(line);
  std::string token;
  in >> token;  // the tag
  while (in >> token) {
    float value = 0;
    auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    REQUIRE(ec == std::errc());
    REQUIRE(ptr == token.data() + token.size());
    values.push_back(value);
  }
  return values;
}

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

uint32_t u32At(const std::string& bytes, size_t offset) {
  uint32_t value = 0;
  for (int k = 3; k >= 0; --k) value = (value << 8) | uint8_t(bytes[offset + k]);
  return value;
}

float f32At(const std::string& bytes, size_t offset) {
  uint32_t bits = u32At(bytes, offset);
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

// A unit square as two triangles, with values that need all nine significant digits.
TriangleMesh square() {
  TriangleMesh mesh;
  mesh.positions = {{0.1f, 1.0f / 3.0f, -2.5e-8f},
                    {1.0f, 0.0f, 16777215.0f},
                    {1.0f, 1.0f, -0.0f},
                    {0.0f, 1.0f, 3.14159274f}};
  mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0.6f, 0, 0.8f}, {0, 0, 1}};
  mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0.7f, 1}};
  mesh.patchIds = {0, 0, 0, 0};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

const std::string kPlyHeaderWithNormals =
    "ply\n"
    "format binary_little_endian 1.0\n"
    "comment Tessera triangle mesh\n"
    "element vertex 4\n"
    "property float x\n"
    "property float y\n"
    "property float z\n"
    "property float nx\n"
    "property float ny\n"
    "property float nz\n"
    "element face 2\n"
    "property list uchar uint vertex_indices\n"
    "end_header\n";

}  // namespace

TEST_CASE("mesh: validate accepts consistent meshes and rejects broken ones", "[io][mesh]") {
  CHECK_NOTHROW(square().validate());
  CHECK_NOTHROW(TriangleMesh{}.validate());
  TriangleMesh positionsOnly = square();
  positionsOnly.normals.clear();
  positionsOnly.uvs.clear();
  positionsOnly.patchIds.clear();
  CHECK_NOTHROW(positionsOnly.validate());

  TriangleMesh m = square();
  m.normals.pop_back();
  CHECK_THROWS_WITH(m.validate(), Catch::Contains("normals has 3 entries for 4 positions"));
  m = square();
  m.uvs.push_back({0, 0});
  CHECK_THROWS_AS(m.validate(), std::invalid_argument);
  m = square();
  m.patchIds.resize(1);
  CHECK_THROWS_AS(m.validate(), std::invalid_argument);
  m = square();
  m.indices.push_back(0);
  CHECK_THROWS_WITH(m.validate(), Catch::Contains("not a multiple of 3"));
  m = square();
  m.indices[4] = 4;
  CHECK_THROWS_WITH(m.validate(), Catch::Contains("index 4 is 4, but there are only 4 vertices"));
  m = square();
  m.positions[2].y = std::numeric_limits<float>::quiet_NaN();
  CHECK_THROWS_WITH(m.validate(), Catch::Contains("positions[2] is not finite"));
  m = square();
  m.normals[1].x = std::numeric_limits<float>::infinity();
  CHECK_THROWS_AS(m.validate(), std::invalid_argument);
}

TEST_CASE("obj: positions, uvs, normals and faces parse back", "[io][obj]") {
  ScratchDir dir("mesh");
  const TriangleMesh mesh = square();
  const fs::path path = dir.path / "square.obj";
  writeObjFile(path.string(), mesh);
  const auto all = lines(test::readWholeFile(path));

  CHECK(countPrefix(all, "v ") == 4);
  CHECK(countPrefix(all, "vt ") == 4);
  CHECK(countPrefix(all, "vn ") == 4);
  CHECK(countPrefix(all, "f ") == 2);
  CHECK(all.size() == 1 + 4 + 4 + 4 + 2);  // plus the comment line
  CHECK(all[0].rfind("#", 0) == 0);

  // Every float reads back bit for bit (including -0).
  std::vector<std::string> vLines, vnLines, vtLines;
  for (const auto& l : all) {
    if (l.rfind("v ", 0) == 0) vLines.push_back(l);
    if (l.rfind("vn ", 0) == 0) vnLines.push_back(l);
    if (l.rfind("vt ", 0) == 0) vtLines.push_back(l);
  }
  for (size_t v = 0; v < 4; ++v) {
    const auto p = floatsAfterTag(vLines[v]);
    const auto n = floatsAfterTag(vnLines[v]);
    const auto t = floatsAfterTag(vtLines[v]);
    REQUIRE(p.size() == 3);
    REQUIRE(n.size() == 3);
    REQUIRE(t.size() == 2);
    for (int c = 0; c < 3; ++c) {
      CHECK(sameBits(p[c], mesh.positions[v][c]));
      CHECK(sameBits(n[c], mesh.normals[v][c]));
    }
    for (int c = 0; c < 2; ++c) CHECK(sameBits(t[c], mesh.uvs[v][c]));
  }
  CHECK(vLines[0] == "v 0.1 0.33333334 -2.5e-08");
  CHECK(countPrefix(all, "f 1/1/1 2/2/2 3/3/3") == 1);
  CHECK(countPrefix(all, "f 1/1/1 3/3/3 4/4/4") == 1);
}

TEST_CASE("obj: face forms follow the attributes present", "[io][obj]") {
  TriangleMesh mesh = square();
  auto faceLines = [](const TriangleMesh& m) {
    std::ostringstream out;
    writeObj(out, m);
    std::vector<std::string> faces;
    for (const auto& l : lines(out.str()))
      if (l.rfind("f ", 0) == 0) faces.push_back(l);
    return faces;
  };

  mesh.uvs.clear();
  CHECK(faceLines(mesh) == std::vector<std::string>{"f 1//1 2//2 3//3", "f 1//1 3//3 4//4"});
  mesh = square();
  mesh.normals.clear();
  CHECK(faceLines(mesh) == std::vector<std::string>{"f 1/1 2/2 3/3", "f 1/1 3/3 4/4"});
  mesh.uvs.clear();
  CHECK(faceLines(mesh) == std::vector<std::string>{"f 1 2 3", "f 1 3 4"});

  std::ostringstream out;
  writeObj(out, mesh);
  const auto all = lines(out.str());
  CHECK(countPrefix(all, "vn ") == 0);
  CHECK(countPrefix(all, "vt ") == 0);
}

TEST_CASE("ply: header and byte size are exact", "[io][ply]") {
  ScratchDir dir("mesh");
  const TriangleMesh mesh = square();

  SECTION("with normals") {
    const fs::path path = dir.path / "square.ply";
    writePlyFile(path.string(), mesh);
    const std::string bytes = test::readWholeFile(path);
    const size_t headerSize = kPlyHeaderWithNormals.size();
    REQUIRE(bytes.size() == headerSize + 4 * 6 * 4 + 2 * (1 + 3 * 4));
    CHECK(bytes.substr(0, headerSize) == kPlyHeaderWithNormals);

    // Vertex 1: position then normal, little-endian fp32.
    const size_t v1 = headerSize + 24;
    CHECK(sameBits(f32At(bytes, v1 + 0), 1.0f));
    CHECK(sameBits(f32At(bytes, v1 + 8), 16777215.0f));
    const size_t v2 = headerSize + 2 * 24;
    CHECK(sameBits(f32At(bytes, v2 + 8), -0.0f));
    CHECK(sameBits(f32At(bytes, v2 + 12), 0.6f));
    CHECK(sameBits(f32At(bytes, v2 + 20), 0.8f));
    // Face 1: count 3, then indices 0 2 3.
    const size_t f1 = headerSize + 4 * 24 + 13;
    CHECK(uint8_t(bytes[f1]) == 3);
    CHECK(u32At(bytes, f1 + 1) == 0);
    CHECK(u32At(bytes, f1 + 5) == 2);
    CHECK(u32At(bytes, f1 + 9) == 3);
  }
  SECTION("without normals") {
    TriangleMesh plain = mesh;
    plain.normals.clear();
    std::ostringstream out;
    writePly(out, plain);
    const std::string bytes = out.str();
    const std::string header =
        "ply\n"
        "format binary_little_endian 1.0\n"
        "comment Tessera triangle mesh\n"
        "element vertex 4\n"
        "property float x\n"
        "property float y\n"
        "property float z\n"
        "element face 2\n"
        "property list uchar uint vertex_indices\n"
        "end_header\n";
    REQUIRE(bytes.size() == header.size() + 4 * 12 + 2 * 13);
    CHECK(bytes.substr(0, header.size()) == header);
    CHECK(sameBits(f32At(bytes, header.size()), 0.1f));
    CHECK(sameBits(f32At(bytes, header.size() + 4), 1.0f / 3.0f));
  }
  SECTION("an empty mesh is a header only") {
    std::ostringstream out;
    writePly(out, TriangleMesh{});
    CHECK(out.str().find("element vertex 0\n") != std::string::npos);
    CHECK(out.str().find("element face 0\n") != std::string::npos);
    CHECK(out.str().size() == out.str().find("end_header\n") + 11);
  }
}

TEST_CASE("mesh writers: bad meshes and bad paths leave no file behind", "[io][obj][ply]") {
  ScratchDir dir("mesh");
  TriangleMesh broken = square();
  broken.indices[5] = 99;
  const fs::path obj = dir.path / "broken.obj";
  const fs::path ply = dir.path / "broken.ply";
  CHECK_THROWS_AS(writeObjFile(obj.string(), broken), std::invalid_argument);
  CHECK_THROWS_AS(writePlyFile(ply.string(), broken), std::invalid_argument);
  CHECK(fs::is_empty(dir.path));

  const std::string missing = (dir.path / "missing" / "square.obj").string();
  try {
    writeObjFile(missing, square());
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.kind() == InputErrorKind::Io);
    CHECK(std::string(e.what()).find(missing) != std::string::npos);
  }
  CHECK_THROWS_AS(writePlyFile((dir.path / "missing" / "square.ply").string(), square()),
                  InputError);
  CHECK(fs::is_empty(dir.path));
}
