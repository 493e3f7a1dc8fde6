// --metadata (host/io/mesh_write_options.h): PLY carries u, v and patch as vertex properties in
// the layout its header declares, OBJ starts each run of one patch's triangles with
// "g patch_<id>"; without the option the files are the same bytes as before.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "io/obj_writer.h"
#include "io/ply_writer.h"
#include "mesh/mesh.h"

using namespace tessera;

namespace {

// Three triangles on two patches, the vertex on the shared edge welded (patch 0's).
TriangleMesh twoPatches() {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}};
  mesh.normals.assign(5, {0, 0, 1});
  mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0.25f, 1}, {1, 0.5f}};
  mesh.patchIds = {0, 0, 0, 0, 7};
  mesh.indices = {0, 1, 2, 0, 2, 3, 1, 4, 2};
  mesh.trianglePatchIds = {0, 0, 7};
  return mesh;
}

MeshWriteOptions withMetadata() {
  MeshWriteOptions options;
  options.metadata = true;
  return options;
}

uint32_t u32At(const std::string& bytes, size_t offset) {
  uint32_t value = 0;
  for (int k = 3; k >= 0; --k) value = (value << 8) | uint8_t(bytes[offset + k]);
  return value;
}

float f32At(const std::string& bytes, size_t offset) {
  const uint32_t bits = u32At(bytes, offset);
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

}  // namespace

TEST_CASE("ply --metadata: u, v and patch as vertex properties", "[io][ply]") {
  const TriangleMesh mesh = twoPatches();
  std::ostringstream out;
  writePly(out, mesh, withMetadata());
  const std::string bytes = out.str();
  const std::string header =
      "ply\n"
      "format binary_little_endian 1.0\n"
      "comment Tessera triangle mesh\n"
      "element vertex 5\n"
      "property float x\n"
      "property float y\n"
      "property float z\n"
      "property float nx\n"
      "property float ny\n"
      "property float nz\n"
      "property float u\n"
      "property float v\n"
      "property uint patch\n"
      "element face 3\n"
      "property list uchar uint vertex_indices\n"
      "end_header\n";
  const size_t vertexBytes = 6 * 4 + 2 * 4 + 4;
  REQUIRE(bytes.size() == header.size() + 5 * vertexBytes + 3 * 13);
  CHECK(bytes.substr(0, header.size()) == header);
  for (size_t v = 0; v < 5; ++v) {
    const size_t at = header.size() + v * vertexBytes;
    CHECK(f32At(bytes, at) == mesh.positions[v].x);
    CHECK(f32At(bytes, at + 24) == mesh.uvs[v].x);
    CHECK(f32At(bytes, at + 28) == mesh.uvs[v].y);
    CHECK(u32At(bytes, at + 32) == mesh.patchIds[v]);
  }
  // The faces follow unchanged.
  const size_t faces = header.size() + 5 * vertexBytes;
  CHECK(uint8_t(bytes[faces + 26]) == 3);
  CHECK(u32At(bytes, faces + 27) == 1);
  CHECK(u32At(bytes, faces + 31) == 4);
}

TEST_CASE("obj --metadata: a group line where the patch changes", "[io][obj]") {
  const TriangleMesh mesh = twoPatches();
  std::ostringstream out;
  writeObj(out, mesh, withMetadata());
  const std::string text = out.str();
  const std::string faces =
      "g patch_0\n"
      "f 1/1/1 2/2/2 3/3/3\n"
      "f 1/1/1 3/3/3 4/4/4\n"
      "g patch_7\n"
      "f 2/2/2 5/5/5 3/3/3\n";
  REQUIRE(text.size() >= faces.size());
  CHECK(text.substr(text.size() - faces.size()) == faces);
}

TEST_CASE("mesh writers without --metadata: the same bytes as before", "[io][obj][ply]") {
  TriangleMesh mesh = twoPatches();
  std::ostringstream objWith, plyWith, objPlain, plyPlain;
  writeObj(objWith, mesh);
  writePly(plyWith, mesh);
  mesh.trianglePatchIds.clear();  // what the writers never looked at before
  writeObj(objPlain, mesh);
  writePly(plyPlain, mesh);
  CHECK(objWith.str() == objPlain.str());
  CHECK(plyWith.str() == plyPlain.str());
  CHECK(objWith.str().find("g ") == std::string::npos);
  CHECK(plyWith.str().find("property uint patch") == std::string::npos);
  // Metadata asked for but absent (a Loop mesh): nothing is added.
  TriangleMesh bare = twoPatches();
  bare.uvs.clear();
  bare.patchIds.clear();
  bare.trianglePatchIds.clear();
  std::ostringstream objBare, objBareMeta;
  writeObj(objBare, bare);
  writeObj(objBareMeta, bare, withMetadata());
  CHECK(objBare.str() == objBareMeta.str());
}

TEST_CASE("mesh: trianglePatchIds must be one per triangle", "[io][mesh]") {
  TriangleMesh mesh = twoPatches();
  mesh.trianglePatchIds.pop_back();
  CHECK_THROWS_AS(mesh.validate(), std::invalid_argument);
}
