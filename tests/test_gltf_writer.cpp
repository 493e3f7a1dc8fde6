// The GLB writer (host/io/gltf_writer.h): the teapot written and parsed back by hand — the
// container, the chunks, the accessors and every attribute value — plus the cases the teapot
// does not reach (zero and non-unit normals, 32-bit indices, no triangles).
// The Khronos glTF validator runs on the teapot and on these samples in CTest
// ("gltf: the Khronos glTF validator ...", tests/CMakeLists.txt); the hidden test case
// "[.gltf-samples]" writes the samples for it.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "io/bpt_reader.h"
#include "io/gltf_writer.h"
#include "mesh/tessellate.h"
#include "glb_reader.h"
#include "scratch_dir.h"

using namespace tessera;
namespace fs = std::filesystem;
using test::ScratchDir;
using namespace tessera::test::glb;
using nlohmann::json;

namespace {

uint32_t bitsOf(float value) {
  uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

const json& primitive(const Glb& glb) {
  return glb.document.at("meshes").at(0).at("primitives").at(0);
}

std::vector<uint32_t> readIndices(const Glb& glb) {
  const AccessorData a = accessor(glb, primitive(glb).at("indices"));
  CHECK(a.target == 34963);
  CHECK(a.type == "SCALAR");
  std::vector<uint32_t> indices(a.count);
  for (size_t k = 0; k < a.count; ++k)
    indices[k] = a.componentType == 5123 ? u16At(glb.bin, a.offset + 2 * k)
                                         : u32At(glb.bin, a.offset + 4 * k);
  return indices;
}

std::vector<glm::vec3> readVec3(const Glb& glb, const char* attribute) {
  const AccessorData a = accessor(glb, primitive(glb).at("attributes").at(attribute));
  CHECK(a.target == 34962);
  CHECK(a.componentType == 5126);
  CHECK(a.type == "VEC3");
  std::vector<glm::vec3> values(a.count);
  for (size_t k = 0; k < a.count; ++k)
    for (int c = 0; c < 3; ++c) values[k][c] = f32At(glb.bin, a.offset + 12 * k + 4 * c);
  return values;
}

Glb writeAndParse(const TriangleMesh& mesh) {
  std::ostringstream out;
  writeGlb(out, mesh);
  return parseGlb(out.str());
}

// A flat n×n grid of unit squares in z = 0, counter-clockwise seen from +z, normals +z.
TriangleMesh flatGrid(uint32_t n) {
  TriangleMesh mesh;
  for (uint32_t j = 0; j < n; ++j)
    for (uint32_t i = 0; i < n; ++i) {
      mesh.positions.push_back({float(i), float(j), 0.0f});
      mesh.normals.push_back({0.0f, 0.0f, 1.0f});
    }
  for (uint32_t j = 0; j + 1 < n; ++j)
    for (uint32_t i = 0; i + 1 < n; ++i) {
      const uint32_t a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, c});
    }
  return mesh;
}

// A square pyramid with its apex at (0, 0, 1): the apex normal is zero (the tessellator's "no
// normal"), so the writer has to find one; the sides' face normals add up to +z.
TriangleMesh pyramidWithZeroApexNormal() {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 1}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {-1, -1, 0}};
  mesh.normals = {{0, 0, 0}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}, {-1, -1, 1}};
  mesh.indices = {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1};
  return mesh;
}

// The files the CTest validator test checks besides the teapot.
std::map<std::string, TriangleMesh> validatorSamples() {
  std::map<std::string, TriangleMesh> samples;
  samples["zero_normals.glb"] = pyramidWithZeroApexNormal();
  TriangleMesh odd = flatGrid(3);  // 8 triangles: 24 16-bit indices = 48 bytes; one more: pad
  odd.normals[4] = {0, 0, 0};
  odd.normals[0] = {0, 0, 5};
  odd.normals[1] = {0, 0, 1e-30f};
  odd.indices.resize(odd.indices.size() - 3);
  samples["odd_normals_short_indices.glb"] = odd;
  samples["int_indices.glb"] = flatGrid(256);  // 65536 vertices: 32-bit indices
  samples["no_triangles.glb"] = TriangleMesh{};
  return samples;
}

}  // namespace

TEST_CASE("gltf: the teapot parses back to the mesh, bit for bit", "[gltf]") {
  const std::vector<BezierPatch> patches = readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt");
  Backend backend = makeMirrorBackend();
  const Tessellation t = tessellate(patches, QuadtreeOptions{}, backend);
  const TriangleMesh& mesh = t.mesh;
  REQUIRE(mesh.triangleCount() > 0);

  ScratchDir dir("gltf");
  const fs::path path = dir.path / "teapot.glb";
  writeGlbFile(path.string(), mesh);
  const std::string bytes = test::readWholeFile(path);
  const Glb glb = parseGlb(bytes);
  REQUIRE_FALSE(glb.bin.empty());
  const json& doc = glb.document;

  CHECK(doc.at("asset").at("version") == "2.0");
  CHECK(doc.at("asset").at("generator") == "tessera");
  CHECK(doc.at("scene") == 0);
  CHECK(doc.at("scenes").at(0).at("nodes") == json::array({0}));
  CHECK(doc.at("nodes").at(0).at("mesh") == 0);
  REQUIRE(doc.at("buffers").size() == 1);
  const size_t bufferLength = doc.at("buffers").at(0).at("byteLength");
  CHECK(bufferLength <= glb.bin.size());
  CHECK(glb.bin.size() - bufferLength < 4);
  CHECK(primitive(glb).at("mode") == 4);

  // Accessor counts and index width.
  const AccessorData indexData = accessor(glb, primitive(glb).at("indices"));
  CHECK(indexData.count == mesh.indices.size());
  CHECK(indexData.componentType == (mesh.vertexCount() <= 65535 ? 5123 : 5125));
  CHECK(readIndices(glb) == mesh.indices);

  // POSITION: every value bit for bit, min and max exactly the componentwise extremes.
  const std::vector<glm::vec3> positions = readVec3(glb, "POSITION");
  REQUIRE(positions.size() == mesh.vertexCount());
  size_t differing = 0;
  for (size_t v = 0; v < positions.size(); ++v)
    for (int c = 0; c < 3; ++c) differing += bitsOf(positions[v][c]) != bitsOf(mesh.positions[v][c]);
  CHECK(differing == 0);
  const json& positionAccessor = doc.at("accessors").at(primitive(glb).at("attributes").at("POSITION").get<int>());
  for (int c = 0; c < 3; ++c) {
    float lo = mesh.positions[0][c], hi = lo;
    for (const glm::vec3& p : mesh.positions) {
      lo = std::min(lo, p[c]);
      hi = std::max(hi, p[c]);
    }
    CHECK(positionAccessor.at("min").at(c).get<double>() == double(lo));
    CHECK(positionAccessor.at("max").at(c).get<double>() == double(hi));
  }

  // NORMAL: unit length, along the mesh's normal wherever that has a direction.
  const std::vector<glm::vec3> normals = readVec3(glb, "NORMAL");
  REQUIRE(normals.size() == mesh.vertexCount());
  double worstLength = 0, worstAngle = 0;
  for (size_t v = 0; v < normals.size(); ++v) {
    worstLength = std::max(worstLength, std::abs(glm::length(glm::dvec3(normals[v])) - 1.0));
    if (mesh.normals[v] != glm::vec3(0))
      worstAngle = std::max(worstAngle, 1.0 - glm::dot(glm::dvec3(normals[v]),
                                                       glm::normalize(glm::dvec3(mesh.normals[v]))));
  }
  INFO("largest | |n| - 1 |: " << worstLength << ", largest 1 - cos: " << worstAngle);
  CHECK(worstLength < 1e-6);
  CHECK(worstAngle < 1e-6);

  // TEXCOORD_0 bit for bit, _PATCH_ID exactly.
  const AccessorData uv = accessor(glb, primitive(glb).at("attributes").at("TEXCOORD_0"));
  CHECK(uv.type == "VEC2");
  REQUIRE(uv.count == mesh.vertexCount());
  differing = 0;
  for (size_t v = 0; v < uv.count; ++v)
    for (int c = 0; c < 2; ++c)
      differing += bitsOf(f32At(glb.bin, uv.offset + 8 * v + 4 * c)) != bitsOf(mesh.uvs[v][c]);
  CHECK(differing == 0);
  const AccessorData ids = accessor(glb, primitive(glb).at("attributes").at("_PATCH_ID"));
  REQUIRE(ids.count == mesh.vertexCount());
  differing = 0;
  for (size_t v = 0; v < ids.count; ++v)
    differing += f32At(glb.bin, ids.offset + 4 * v) != float(mesh.patchIds[v]);
  CHECK(differing == 0);
}

TEST_CASE("gltf: zero and non-unit normals are written as unit vectors", "[gltf]") {
  SECTION("a zero normal takes the direction of its triangles' normals") {
    const Glb glb = writeAndParse(pyramidWithZeroApexNormal());
    const std::vector<glm::vec3> normals = readVec3(glb, "NORMAL");
    CHECK(normals[0] == glm::vec3(0, 0, 1));
    for (size_t v = 1; v < normals.size(); ++v)
      CHECK(std::abs(glm::length(normals[v]) - 1.0f) < 1e-6f);
  }
  SECTION("long, tiny and zero normals on a flat grid all become +z") {
    const Glb glb = writeAndParse(validatorSamples().at("odd_normals_short_indices.glb"));
    for (const glm::vec3& n : readVec3(glb, "NORMAL")) CHECK(n == glm::vec3(0, 0, 1));
  }
  SECTION("a zero normal whose triangles cancel falls back to +z") {
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.normals = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    mesh.indices = {0, 1, 2, 0, 2, 1};  // the same triangle both ways round
    for (const glm::vec3& n : readVec3(writeAndParse(mesh), "NORMAL")) CHECK(n == glm::vec3(0, 0, 1));
  }
}

TEST_CASE("gltf: 16-bit indices up to 65535 vertices, 32-bit beyond", "[gltf]") {
  TriangleMesh mesh;
  mesh.positions.assign(65535, glm::vec3(0));
  for (size_t v = 0; v < mesh.positions.size(); ++v) mesh.positions[v].x = float(v);
  mesh.positions[1].y = 1;
  mesh.indices = {0, 65534, 1};
  Glb glb = writeAndParse(mesh);
  CHECK(accessor(glb, primitive(glb).at("indices")).componentType == 5123);
  CHECK(readIndices(glb) == mesh.indices);
  // 3 indices of 2 bytes: the buffer is 6 bytes past the positions, the chunk pads to 8.
  CHECK(glb.document.at("buffers").at(0).at("byteLength") == 65535 * 12 + 6);
  CHECK(glb.bin.size() == 65535 * 12 + 8);
  CHECK_FALSE(primitive(glb).at("attributes").contains("NORMAL"));
  CHECK_FALSE(primitive(glb).at("attributes").contains("TEXCOORD_0"));

  mesh.positions.push_back({1, 2, 3});
  mesh.indices = {0, 65535, 1};
  glb = writeAndParse(mesh);
  CHECK(accessor(glb, primitive(glb).at("indices")).componentType == 5125);
  CHECK(readIndices(glb) == mesh.indices);
}

TEST_CASE("gltf: a mesh without triangles is a valid empty scene", "[gltf]") {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}};
  std::ostringstream out;
  writeGlb(out, mesh);
  const Glb glb = parseGlb(out.str());
  CHECK(glb.bin.empty());
  CHECK(glb.document.at("scenes").size() == 1);
  CHECK_FALSE(glb.document.contains("meshes"));
  CHECK_FALSE(glb.document.contains("buffers"));
}

TEST_CASE("gltf: an invalid mesh throws and leaves the file as it was", "[gltf]") {
  ScratchDir dir("gltf");
  const fs::path path = dir.path / "kept.glb";
  { std::ofstream(path) << "before"; }
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}};
  mesh.indices = {0, 1, 2};
  CHECK_THROWS_AS(writeGlbFile(path.string(), mesh), std::invalid_argument);
  CHECK(test::readWholeFile(path) == "before");
}

TEST_CASE("gltf: B-rep faces become one primitive each, sharing the vertices", "[gltf]") {
  const TriangleMesh mesh = flatGrid(4);  // 18 triangles
  std::vector<uint32_t> faces(mesh.triangleCount());
  for (size_t t = 0; t < faces.size(); ++t) faces[t] = t % 3 == 0 ? 7 : 2;  // faces 2 and 7
  std::ostringstream out;
  writeGlb(out, mesh, &faces);
  const Glb glb = parseGlb(out.str());
  const json& primitives = glb.document.at("meshes").at(0).at("primitives");
  REQUIRE(primitives.size() == 2);
  std::vector<uint32_t> seen;
  for (size_t k = 0; k < primitives.size(); ++k) {
    const json& p = primitives[k];
    const uint32_t face = p.at("extras").at("face");
    CHECK(face == (k == 0 ? 2u : 7u));  // increasing face order
    CHECK(p.at("attributes") == primitives[0].at("attributes"));
    const AccessorData a = accessor(glb, p.at("indices"));
    std::vector<uint32_t> expected;
    for (size_t t = 0; t < faces.size(); ++t)
      if (faces[t] == face) expected.insert(expected.end(), &mesh.indices[3 * t], &mesh.indices[3 * t] + 3);
    REQUIRE(a.count == expected.size());
    for (size_t i = 0; i < a.count; ++i) CHECK(u16At(glb.bin, a.offset + 2 * i) == expected[i]);
    seen.insert(seen.end(), expected.begin(), expected.end());
  }
  CHECK(seen.size() == mesh.indices.size());
  faces.pop_back();
  CHECK_THROWS_AS(writeGlb(out, mesh, &faces), std::invalid_argument);
}

// An assembly's part placed again (cad/instances.h): the faces of the part go to a mesh of its
// own, drawn at its first place and by a node per placement with its matrix and face offset;
// only the mesh's first vertices and triangles are written (the placements' copies after them
// are the nodes' to draw).
GlbInstances gridInstances(const TriangleMesh& grid) {
  GlbInstances instances;
  instances.vertices = grid.vertexCount();
  instances.triangles = grid.triangleCount();
  instances.parts = {{2, 2}};  // faces 2 and 3
  GlbInstances::Placement placed;
  placed.matrix = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 10, 0, 0, 1};  // 10 along x
  placed.faceOffset = 40;
  instances.placements = {placed};
  return instances;
}

TEST_CASE("gltf: an assembly's part placed twice is one mesh and two nodes", "[gltf]") {
  TriangleMesh mesh = flatGrid(5);  // 32 triangles
  std::vector<uint32_t> faces(mesh.triangleCount());
  for (size_t t = 0; t < faces.size(); ++t) faces[t] = uint32_t(t / 8);  // faces 0..3
  const GlbInstances instances = gridInstances(mesh);
  // A copy after the written prefix, as addInstanceCopies appends it: left out of the file.
  TriangleMesh withCopy = mesh;
  std::vector<uint32_t> withCopyFaces = faces;
  for (size_t t = 16; t < 32; ++t) {
    for (int c = 0; c < 3; ++c) {
      withCopy.positions.push_back(mesh.positions[mesh.indices[3 * t + c]] + glm::vec3(10, 0, 0));
      withCopy.normals.push_back(mesh.normals[mesh.indices[3 * t + c]]);
      withCopy.indices.push_back(uint32_t(withCopy.positions.size() - 1));
    }
    withCopyFaces.push_back(faces[t] + 40);
  }
  std::ostringstream out, plain;
  writeGlb(out, withCopy, &withCopyFaces, &instances);
  writeGlb(plain, mesh, &faces);
  const Glb glb = parseGlb(out.str());
  const json& meshes = glb.document.at("meshes");
  REQUIRE(meshes.size() == 2);
  CHECK(meshes[0].at("primitives").size() == 2);    // faces 0 and 1, in place
  REQUIRE(meshes[1].at("primitives").size() == 2);  // the part's faces 2 and 3
  CHECK(meshes[1].at("primitives")[0].at("extras").at("face") == 2);
  CHECK(meshes[1].at("primitives")[1].at("extras").at("face") == 3);
  const json& nodes = glb.document.at("nodes");
  REQUIRE(nodes.size() == 3);
  CHECK(nodes[0] == json{{"mesh", 0}});
  CHECK(nodes[1] == json{{"mesh", 1}});
  CHECK(nodes[2].at("mesh") == 1);
  CHECK(nodes[2].at("matrix") == json(instances.placements[0].matrix));
  CHECK(nodes[2].at("extras").at("faceOffset") == 40);
  CHECK(glb.document.at("scenes").at(0).at("nodes") == json{0, 1, 2});
  // The same vertices and indices as the mesh without its copy: the copy is the node's.
  const Glb flat = parseGlb(plain.str());
  CHECK(glb.bin == flat.bin);
  CHECK(accessor(glb, 0).count == mesh.vertexCount());

  GlbInstances past = instances;
  past.triangles = withCopy.triangleCount() + 1;
  CHECK_THROWS_AS(writeGlb(out, withCopy, &withCopyFaces, &past), std::invalid_argument);
  CHECK_THROWS_AS(writeGlb(out, withCopy, nullptr, &instances), std::invalid_argument);
  GlbInstances noSuchPart = instances;
  noSuchPart.placements[0].part = 1;
  CHECK_THROWS_AS(writeGlb(out, withCopy, &withCopyFaces, &noSuchPart), std::invalid_argument);
}

// Hidden: run by CTest as the setup of the validator test, not in the normal suite.
TEST_CASE("gltf: write the validator's sample files", "[.gltf-samples]") {
  const fs::path dir = fs::path(TESSERA_BINARY_DIR) / "tests" / "gltf_samples";
  fs::create_directories(dir);
  for (const auto& [name, mesh] : validatorSamples()) writeGlbFile((dir / name).string(), mesh);
  const TriangleMesh grid = flatGrid(5);
  std::vector<uint32_t> faces(grid.triangleCount());
  for (size_t t = 0; t < faces.size(); ++t) faces[t] = uint32_t(t / 8);
  writeGlbFile((dir / "face_primitives.glb").string(), grid, &faces);
  const GlbInstances instances = gridInstances(grid);
  writeGlbFile((dir / "instances.glb").string(), grid, &faces, &instances);
}
