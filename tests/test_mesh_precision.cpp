// --precision double in the writers (host/io/mesh_write_options.h): OBJ positions and normals
// read back to the very doubles given, PLY declares `double` properties and carries the bits;
// without double copies the fp32 values are widened; fp32 output is unchanged; the
// tessellation's vertices evaluated again in double lie within fp32 rounding of the GPU's.
#include <catch2/catch.hpp>

#include <charconv>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>

#include "geometry/bezier.h"
#include "io/bpt_reader.h"
#include "io/obj_reader.h"
#include "io/obj_writer.h"
#include "io/ply_writer.h"
#include "mesh/double_vertices.h"
#include "mesh/mesh.h"
#include "mesh/tessellate.h"

using namespace tessera;

namespace {

// Two triangles whose double positions need all 17 significant digits.
TriangleMesh preciseSquare() {
  TriangleMesh mesh;
  mesh.positionsDouble = {{0.1, 1.0 / 3.0, -2.5e-8},
                          {1.0 + 1e-15, 0.0, 16777215.000000002},
                          {1.0, 1.0, -0.0},
                          {0.0, 1.0, 3.141592653589793}};
  for (const glm::dvec3& p : mesh.positionsDouble) mesh.positions.push_back(glm::vec3(p));
  mesh.normalsDouble = {{0, 0, 1}, {0, 0, 1}, {0.6, 0, 0.8}, {1 / std::sqrt(2.0), 0, 1 / std::sqrt(2.0)}};
  for (const glm::dvec3& n : mesh.normalsDouble) mesh.normals.push_back(glm::vec3(n));
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

double f64At(const std::string& bytes, size_t offset) {
  uint64_t bits = 0;
  for (int k = 7; k >= 0; --k) bits = (bits << 8) | uint8_t(bytes[offset + k]);
  double value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

MeshWriteOptions inDouble() {
  MeshWriteOptions options;
  options.precision = MeshPrecision::Double;
  return options;
}

}  // namespace

TEST_CASE("obj --precision double: positions read back to the same doubles", "[io][obj]") {
  const TriangleMesh mesh = preciseSquare();
  std::ostringstream out;
  writeObj(out, mesh, inDouble());
  std::istringstream in(out.str());
  const PolygonMesh back = parseObj(in, "square.obj");
  REQUIRE(back.positions.size() == 4);
  double worst = 0;
  for (size_t v = 0; v < 4; ++v)
    for (int c = 0; c < 3; ++c) {
      CHECK(back.positions[v][c] == mesh.positionsDouble[v][c]);
      worst = std::max(worst, std::abs(back.positions[v][c] - mesh.positionsDouble[v][c]));
    }
  WARN("largest difference read back from a double OBJ: " << worst);
  // The 17-digit forms are there, and the normal too.
  CHECK(out.str().find("v 1.000000000000001 0 16777215.000000002\n") != std::string::npos);
  CHECK(out.str().find("vn 0.7071067811865475 0 0.7071067811865475\n") != std::string::npos);
  // fp32 output is what it always was: the float's shortest form.
  std::ostringstream floats;
  writeObj(floats, mesh);
  CHECK(floats.str().find("v 1 0 16777215\n") != std::string::npos);
}

TEST_CASE("obj --precision double without double copies widens the floats exactly", "[io][obj]") {
  TriangleMesh mesh = preciseSquare();
  mesh.positionsDouble.clear();
  mesh.normalsDouble.clear();
  std::ostringstream out;
  writeObj(out, mesh, inDouble());
  std::istringstream in(out.str());
  const PolygonMesh back = parseObj(in, "square.obj");
  for (size_t v = 0; v < 4; ++v)
    for (int c = 0; c < 3; ++c) CHECK(back.positions[v][c] == double(mesh.positions[v][c]));
}

TEST_CASE("ply --precision double: double properties and their bits", "[io][ply]") {
  const TriangleMesh mesh = preciseSquare();
  std::ostringstream out;
  writePly(out, mesh, inDouble());
  const std::string bytes = out.str();
  const std::string header =
      "ply\n"
      "format binary_little_endian 1.0\n"
      "comment Tessera triangle mesh\n"
      "element vertex 4\n"
      "property double x\n"
      "property double y\n"
      "property double z\n"
      "property double nx\n"
      "property double ny\n"
      "property double nz\n"
      "element face 2\n"
      "property list uchar uint vertex_indices\n"
      "end_header\n";
  REQUIRE(bytes.size() == header.size() + 4 * 6 * 8 + 2 * 13);
  CHECK(bytes.substr(0, header.size()) == header);
  for (size_t v = 0; v < 4; ++v)
    for (int c = 0; c < 3; ++c) {
      CHECK(f64At(bytes, header.size() + 48 * v + 8 * c) == mesh.positionsDouble[v][c]);
      CHECK(f64At(bytes, header.size() + 48 * v + 24 + 8 * c) == mesh.normalsDouble[v][c]);
    }
}

TEST_CASE("mesh: double copies must match the positions and be finite", "[io][mesh]") {
  TriangleMesh mesh = preciseSquare();
  mesh.positionsDouble.pop_back();
  CHECK_THROWS_AS(mesh.validate(), std::invalid_argument);
  mesh = preciseSquare();
  mesh.normalsDouble[2].y = std::nan("");
  CHECK_THROWS_AS(mesh.validate(), std::invalid_argument);
}

TEST_CASE("tessellation vertices in double: the same points, to fp32 rounding", "[mesh]") {
  const std::vector<BezierPatch> patches = readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt");
  Backend backend = makeMirrorBackend();
  QuadtreeOptions options;
  options.rule = SplitRule::Midpoint;
  Tessellation t = tessellate(patches, options, backend);
  evaluateVerticesInDouble(t.mesh, patches);
  const TriangleMesh& mesh = t.mesh;
  REQUIRE(mesh.positionsDouble.size() == mesh.vertexCount());
  REQUIRE(mesh.normalsDouble.size() == mesh.vertexCount());
  double worstPosition = 0, worstNormal = 0;
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    const glm::dvec3 exact =
        patchPoint(patches[mesh.patchIds[v]], mesh.uvs[v].x, mesh.uvs[v].y);
    REQUIRE(mesh.positionsDouble[v] == exact);
    worstPosition = std::max(worstPosition, glm::length(exact - glm::dvec3(mesh.positions[v])));
    if (glm::length(mesh.normals[v]) > 0.5f)
      worstNormal = std::max(worstNormal, glm::length(mesh.normalsDouble[v] -
                                                      glm::dvec3(mesh.normals[v])));
  }
  WARN("teapot rule B, " << mesh.vertexCount() << " vertices: double vs fp32 mirror positions "
                         << worstPosition << ", unit normals " << worstNormal);
  // The teapot is about 6 wide: fp32 evaluation is good to a few ulps of that (~1e-6).
  CHECK(worstPosition < 1e-5);
  CHECK(worstNormal < 1e-3);
}
