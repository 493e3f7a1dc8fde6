// The OBJ polygon-mesh reader and its topology checks (host/io/obj_reader.h): every corner
// form and index convention reads, and each kind of malformed file or mesh is rejected with
// the right error kind, file name, line and reason.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

#include "input_error_checks.h"
#include "io/errors.h"
#include "io/obj_reader.h"

using namespace tessera;

namespace {

PolygonMesh parse(const std::string& text, const std::string& name = "test.obj") {
  std::istringstream in(text);
  return parseObj(in, name);
}


void parseOnly(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  parseObj(in, name);
}

void parseAndRequireManifold(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  validateManifold(parseObj(in, name), name);
}

// Four vertices of a unit square in z = 0 (lines 1–4).
const std::string kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

}  // namespace

TEST_CASE("obj: corner forms, relative indices and ignored statements", "[io][obj]") {
  const std::string text =
      "# a cube's bottom and one side\r\n"                   // 1
      "mtllib cube.mtl\r\n"                                   // 2
      "o cube\r\n"                                            // 3
      "v 0 0 0\r\n"                                           // 4
      "v 1 0 0 1.0\n"                                         // 5: with a weight
      "v +1 1 0 0.5 0.5 0.5\n"                                // 6: with a colour
      "  v   0\t1  0   # trailing comment\n"                  // 7
      "vt 0 0\nvt 1 0\nvt 1 1\n"                              // 8–10
      "vn 0 0 -1\n"                                           // 11
      "\n"                                                    // 12
      "g bottom\ns off\nusemtl grey\n"                        // 13–15
      "f 1 4 3 2\n"                                           // 16: plain
      "f 1/1 2/2 3/3\n"                                       // 17: v/t
      "f 1//1 3//1 4//1\n"                                    // 18: v//n
      "f 1/1/1 2/2/1 3/3/1\n"                                 // 19: v/t/n
      "f -4 -3 -2 -1\n"                                       // 20: relative
      "f -4/-3/-1 -3/-2/-1 -2/-1/-1\n"                        // 21: relative everywhere
      "v 0 0 1\n"                                             // 22
      "f 1 2 -1 # refers to the vertex just above\n"          // 23
      "l 1 2\np 3\nvp 0.5\n";                                 // 24–26: ignored
  const PolygonMesh mesh = parse(text);
  REQUIRE(mesh.positions.size() == 5);
  CHECK(mesh.positions[0] == glm::dvec3(0, 0, 0));
  CHECK(mesh.positions[1] == glm::dvec3(1, 0, 0));
  CHECK(mesh.positions[2] == glm::dvec3(1, 1, 0));
  CHECK(mesh.positions[3] == glm::dvec3(0, 1, 0));
  CHECK(mesh.positions[4] == glm::dvec3(0, 0, 1));
  REQUIRE(mesh.faces.size() == 7);
  CHECK(mesh.faces[0] == std::vector<uint32_t>{0, 3, 2, 1});
  CHECK(mesh.faces[1] == std::vector<uint32_t>{0, 1, 2});
  CHECK(mesh.faces[2] == std::vector<uint32_t>{0, 2, 3});
  CHECK(mesh.faces[3] == std::vector<uint32_t>{0, 1, 2});
  CHECK(mesh.faces[4] == std::vector<uint32_t>{0, 1, 2, 3});
  CHECK(mesh.faces[5] == std::vector<uint32_t>{0, 1, 2});
  CHECK(mesh.faces[6] == std::vector<uint32_t>{0, 1, 4});
  CHECK(mesh.faceLines == std::vector<int>{16, 17, 18, 19, 20, 21, 23});
}

TEST_CASE("obj: positive indices may refer to vertices defined later", "[io][obj]") {
  const PolygonMesh mesh = parse("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
  REQUIRE(mesh.faces.size() == 1);
  CHECK(mesh.faces[0] == std::vector<uint32_t>{0, 1, 2});
}

TEST_CASE("obj: malformed files name the error kind, file, line and reason", "[io][obj]") {
  test::checkBadTexts(
      {
          {"empty.obj", "", InputErrorKind::Count, 1,
           "empty mesh: no vertices (\"v\") and no faces (\"f\")"},
          {"only_comments.obj", "# nothing\n\ng group\n", InputErrorKind::Count, 4,
           "empty mesh"},
          {"no_faces.obj", kSquare, InputErrorKind::Count, 5,
           "no faces (\"f\" lines): not a polygon mesh"},
          {"no_vertices.obj", "f 1 2 3\n", InputErrorKind::Count, 2,
           "no vertices (\"v\" lines) for the faces"},
          {"zero_index.obj", kSquare + "f 1 2 3\nf 1 0 4\n", InputErrorKind::Topology, 6,
           "vertex index 0 is invalid (corner 2 of face 2): OBJ indices start at 1"},
          {"out_of_range.obj", kSquare + "f 1 2 3\n\nf 1 3 5\n", InputErrorKind::Topology, 7,
           "vertex index 5 is out of range: the file has 4 vertices"},
          {"out_of_range_later.obj", kSquare + "f 1 2 9\nv 2 2 2\n", InputErrorKind::Topology, 5,
           "vertex index 9 is out of range: the file has 5 vertices"},
          {"relative_out_of_range.obj", kSquare + "f -1 -2 -5\n", InputErrorKind::Topology, 5,
           "relative vertex index -5 (corner 3 of face 1) reaches before the first one: 4 precede "
           "this line"},
          {"index_overflow.obj", kSquare + "f 1 2 99999999999999999999\n", InputErrorKind::Topology,
           5, "vertex index '99999999999999999999' is out of range (corner 3 of face 1)"},
          {"two_vertex_face.obj", kSquare + "f 1 2 3\nf 1 2\n", InputErrorKind::Topology, 6,
           "face 2 has 2 corners; a face needs at least 3"},
          {"one_vertex_face.obj", kSquare + "f 1 # 2 3\n", InputErrorKind::Topology, 5,
           "face 1 has 1 corner; a face needs at least 3"},
          {"real_index.obj", kSquare + "f 1 2.0 3\n", InputErrorKind::Syntax, 5,
           "'2.0' is not a face corner (corner 2 of face 1; expected v, v/t, v//n or v/t/n with "
           "integers)"},
          {"too_many_slashes.obj", kSquare + "f 1/1/1/1 2 3\n", InputErrorKind::Syntax, 5,
           "'1/1/1/1' is not a face corner (corner 1 of face 1"},
          {"dangling_slash.obj", kSquare + "vt 0 0\nf 1/ 2/1 3/1\n", InputErrorKind::Syntax, 6,
           "'1/' is not a face corner"},
          {"mixed_forms.obj", kSquare + "vt 0 0\nf 1/1 2/1 3\n", InputErrorKind::Syntax, 6,
           "'3' (corner 3 of face 1) mixes corner forms: '1/1' began the face"},
          {"texture_out_of_range.obj", kSquare + "vt 0 0\nf 1/1 2/2 3/1\n",
           InputErrorKind::Topology, 6,
           "texture-coordinate index 2 is out of range: the file has 1 \"vt\" lines"},
          {"normal_zero.obj", kSquare + "vn 0 0 1\nf 1//1 2//0 3//1\n", InputErrorKind::Topology, 6,
           "normal index 0 is invalid (corner 2 of face 1)"},
          {"not_a_number.obj", "v 0 0 0\nv 1 zero 0\n", InputErrorKind::Syntax, 2,
           "'zero' is not a number (y of vertex 2)"},
          {"decimal_comma.obj", "v 0 0 1,5\n", InputErrorKind::Syntax, 1,
           "'1,5' is not a number (z of vertex 1)"},
          {"nan.obj", kSquare + "v nan 0 0\nf 1 2 3\n", InputErrorKind::NonFinite, 5,
           "'nan' is not a finite number (x of vertex 5)"},
          {"inf.obj", "v 0 0 0\nv 0 -inf 0\n", InputErrorKind::NonFinite, 2,
           "'-inf' is not a finite number (y of vertex 2)"},
          {"nan_colour.obj", "v 0 0 0 1 NaN 1\n", InputErrorKind::NonFinite, 1,
           "'NaN' is not a finite number (g of vertex 1)"},
          {"huge.obj", "v 0 0 1e300\n", InputErrorKind::Range, 1,
           "'1e300' exceeds the largest accepted magnitude 1e15 (z of vertex 1)"},
          {"overflow.obj", "v 1e400 0 0\n", InputErrorKind::Range, 1,
           "'1e400' is outside the range of a double (x of vertex 1)"},
          {"two_coordinates.obj", "v 0 0\n", InputErrorKind::Syntax, 1,
           "expected \"v x y z\" (3 numbers; 4 with a weight, 6 with a colour) for vertex 1, "
           "found 2"},
          {"five_numbers.obj", "v 0 0 0 1 1\n", InputErrorKind::Syntax, 1, "found 5"},
          {"unknown_statement.obj", kSquare + "face 1 2 3\n", InputErrorKind::Syntax, 5,
           "unknown OBJ statement 'face'"},
          {"free_form.obj", "cstype bspline\n", InputErrorKind::Syntax, 1,
           "free-form geometry ('cstype') is not supported; only polygonal faces are read"},
      },
      parseOnly);
}

TEST_CASE("obj: validateTriangles names the first other face and its line", "[io][obj]") {
  const PolygonMesh triangles = parse(kSquare + "f 1 2 3\nf 1 3 4\n");
  CHECK_NOTHROW(validateTriangles(triangles, "tris.obj"));

  const PolygonMesh mixed = parse(kSquare + "f 1 2 3\n# a quad\nf 1 2 3 4\nf 1 2 3 4\n");
  try {
    validateTriangles(mixed, "mixed.obj");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.kind() == InputErrorKind::Topology);
    CHECK(e.file() == "mixed.obj");
    CHECK(e.line() == 7);
    CHECK(std::string(e.what()) ==
          "mixed.obj:7: face 2 has 4 corners; only triangles are accepted here");
  }

  PolygonMesh inCode;  // no face lines: the message names the face only
  inCode.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  inCode.faces = {{0, 1, 3, 2}};
  try {
    validateTriangles(inCode, "built");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.line() == 0);
    CHECK(std::string(e.what()) == "built: face 1 has 4 corners; only triangles are accepted here");
  }
}

TEST_CASE("obj: validateManifold accepts closed and open oriented meshes", "[io][obj]") {
  // A tetrahedron, outward normals: closed, every edge in two faces, opposite directions.
  const PolygonMesh tetrahedron =
      parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n");
  CHECK_NOTHROW(validateManifold(tetrahedron, "tetrahedron.obj"));
  // A square with a hole's worth of boundary: two triangles and a quad, all edges ≤ 2 faces.
  const PolygonMesh open = parse(kSquare + "v 2 0 0\nv 2 1 0\nf 1 2 3\nf 1 3 4\nf 2 5 6 3\n");
  CHECK_NOTHROW(validateManifold(open, "open.obj"));
  // A single triangle: all three edges are boundary edges (holes are allowed).
  CHECK_NOTHROW(validateManifold(parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "one.obj"));
}

TEST_CASE("obj: validateManifold names non-manifold edges and flipped faces", "[io][obj]") {
  test::checkBadTexts(
      {
          {"non_manifold_edge.obj",
           kSquare + "v 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 5\n# a fin\nf 1 2 6\n",
           InputErrorKind::Topology, 10,
           "the edge between vertices 1 and 2 is shared by more than two faces: faces 1, 2 and 3 "
           "(lines 7, 8 and 10); not a manifold"},
          {"flipped_face.obj", kSquare + "f 1 2 3\n\nf 1 4 3\n", InputErrorKind::Topology, 7,
           "faces 1 and 2 (lines 5 and 7) both run the edge between vertices 1 and 3 from vertex "
           "3 to vertex 1: inconsistent orientation (one of them is flipped)"},
          {"repeated_vertex.obj", kSquare + "f 1 2 3\nf 1 3 3 4\n", InputErrorKind::Topology, 6,
           "face 2 uses vertex 3 twice: not a manifold surface"},
      },
      parseAndRequireManifold);
}

TEST_CASE("obj: files on disk", "[io][obj]") {
  SECTION("a missing file is an Io error naming it") {
    const InputError e =
        test::inputErrorOf([] { readObj("/nonexistent/mesh.obj"); }, "a missing file");
    CHECK(e.kind() == InputErrorKind::Io);
    CHECK(e.file() == "/nonexistent/mesh.obj");
    CHECK(e.line() == 0);
  }
  SECTION("the bad inputs kept as files") {
    const std::string dir = TESSERA_SOURCE_DIR "/tests/bad_inputs/";
    struct FileCase {
      const char* file;
      bool manifoldCheck;
      int line;
      const char* reason;
    };
    const FileCase cases[] = {
        {"zero_index.obj", false, 4, "vertex index 0 is invalid (corner 1 of face 1)"},
        {"non_manifold_edge.obj", true, 10,
         "the edge between vertices 1 and 2 is shared by more than two faces"},
        {"flipped_face.obj", true, 7, "inconsistent orientation (one of them is flipped)"},
    };
    for (const FileCase& c : cases) {
      const std::string path = dir + c.file;
      INFO(path);
      try {
        const PolygonMesh mesh = readObj(path);
        if (c.manifoldCheck) validateManifold(mesh, path);
        FAIL("no error");
      } catch (const InputError& e) {
        INFO(e.what());
        CHECK(e.kind() == InputErrorKind::Topology);
        CHECK(e.file() == path);
        CHECK(e.line() == c.line);
        CHECK(std::string(e.what()).find(c.reason) != std::string::npos);
      }
    }
  }
}
