// The JSON scene reader (host/io/scene_reader.h): the example scenes read as documented, and
// every kind of malformed scene is rejected with the right error kind, file name, line of the
// offending JSON value and reason.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "input_error_checks.h"
#include "io/errors.h"
#include "io/scene_reader.h"
#include "geometry/rational.h"

using namespace tessera;

namespace {

Scene parse(const std::string& text, const std::string& name = "test.json") {
  std::istringstream in(text);
  return parseScene(in, name);
}

// A scene of one surface: line 1 opens the scene, the surface's lines follow, the last line
// closes it. `surface` spans lines 2.. of the file.
std::string sceneWith(const std::string& surface) {
  return "{\"tessera_scene\": 1, \"surfaces\": [\n" + surface + "\n]}\n";
}

// A bilinear patch on lines 2–4 (points on lines 3 and 4), with extra members on line 2.
std::string bilinear(const std::string& degree = "[1, 1]", const std::string& extra = "",
                     const std::string& pointsLine3 = "[0, 0, 0], [0, 1, 0],",
                     const std::string& pointsLine4 = "[1, 0, 0], [1, 1, 0]") {
  return "{\"type\": \"bezier\", \"degree\": " + degree + extra + ",\n \"points\": [" +
         pointsLine3 + "\n   " + pointsLine4 + "]}";
}

// A bicubic B-spline of 5 × 4 control points: degree on line 2, knots on lines 3 and 4,
// points on lines 5–9 (one u-row per line).
std::string bspline(const std::string& knotsU = "[0, 0, 0, 0, 0.5, 1, 1, 1, 1]",
                    const std::string& knotsV = "[0, 0, 0, 0, 1, 1, 1, 1]",
                    const std::string& count = "[5, 4]") {
  std::string text = "{\"type\": \"bspline\", \"degree\": [3, 3], \"count\": " + count + ",\n" +
                     " \"knots_u\": " + knotsU + ",\n \"knots_v\": " + knotsV + ",\n \"points\": [";
  for (int i = 0; i < 5; ++i) {
    if (i > 0) text += ",\n  ";
    for (int j = 0; j < 4; ++j)
      text += (j > 0 ? ", [" : "[") + std::to_string(i) + ", " + std::to_string(j) + ", 0]";
  }
  return text + "]}";
}

// Every case must make parseScene throw the InputError it describes.
void checkCases(const std::vector<test::BadTextCase>& cases) {
  test::checkBadTexts(cases, [](const std::string& text, const std::string& name) {
    std::istringstream in(text);
    parseScene(in, name);
  });
}

}  // namespace

TEST_CASE("scene: the example reads as documented", "[io][scene]") {
  const Scene scene = readScene(TESSERA_SOURCE_DIR "/data/scene_example.json");
  REQUIRE(scene.bezier.size() == 2);
  REQUIRE(scene.rational.empty());
  REQUIRE(scene.bsplines.size() == 1);
  REQUIRE(scene.order.size() == 3);
  CHECK(scene.source == TESSERA_SOURCE_DIR "/data/scene_example.json");

  CHECK(scene.order[0].type == SceneSurfaceType::Bezier);
  CHECK(scene.order[0].index == 0);
  CHECK(scene.order[0].name == "bicubic bump");
  CHECK(scene.order[0].line == 5);
  CHECK(scene.order[0].degreeLine == 8);
  CHECK(scene.order[1].type == SceneSurfaceType::Bezier);
  CHECK(scene.order[1].index == 1);
  CHECK(scene.order[1].name == "biquadratic saddle");
  CHECK(scene.order[2].type == SceneSurfaceType::BSpline);
  CHECK(scene.order[2].name == "wave");

  const BezierPatch& bump = scene.bezier[0];
  CHECK(bump.degreeU == 3);
  CHECK(bump.degreeV == 3);
  REQUIRE(bump.cp.size() == 16);
  CHECK(bump.at(0, 3) == glm::dvec3(0, 3, 0));
  CHECK(bump.at(1, 1) == glm::dvec3(1, 1, 1));
  CHECK(bump.at(3, 0) == glm::dvec3(3, 0, 0));

  const BezierPatch& saddle = scene.bezier[1];
  CHECK(saddle.degreeU == 2);
  CHECK(saddle.degreeV == 2);
  CHECK(saddle.at(0, 0) == glm::dvec3(4, 0, 0.8));
  CHECK(saddle.at(2, 1) == glm::dvec3(6, 1.5, 0));

  const BSplineSurface& wave = scene.bsplines[0];
  CHECK(wave.degreeU == 3);
  CHECK(wave.degreeV == 3);
  CHECK(wave.countU == 5);
  CHECK(wave.countV == 4);
  CHECK(wave.knotsU == std::vector<double>{0, 0, 0, 0, 0.4, 1, 1, 1, 1});
  CHECK(wave.knotsV == std::vector<double>{0, 0, 0, 0, 1, 1, 1, 1});
  REQUIRE(wave.cp.size() == 20);
  CHECK(wave.at(1, 0) == glm::dvec3(8, 0, 0.289067));
}

TEST_CASE("scene: rational patches, an exact quarter circle and a zero inner weight",
          "[io][scene]") {
  const Scene scene = readScene(TESSERA_SOURCE_DIR "/data/scene_rational.json");
  REQUIRE(scene.rational.size() == 2);
  REQUIRE(scene.order.size() == 2);
  CHECK(scene.order[0].type == SceneSurfaceType::Rational);
  CHECK(scene.order[0].weightsLine == 15);

  const RationalBezierPatch& cylinder = scene.rational[0];
  CHECK(cylinder.degreeU == 2);
  CHECK(cylinder.degreeV == 1);
  const double h = std::sqrt(0.5);
  // Homogeneous (w·x, w·y, w·z, w).
  CHECK(cylinder.at(1, 1).x == Approx(h).epsilon(1e-15));
  CHECK(cylinder.at(1, 1).z == Approx(h).epsilon(1e-15));
  CHECK(cylinder.at(1, 1).w == h);
  for (double u : {0.0, 0.1, 0.3, 0.5, 0.77, 1.0})
    for (double v : {0.0, 0.4, 1.0}) {
      const glm::dvec3 p = rationalPatchPoint(cylinder, u, v);
      CHECK(std::hypot(p.x, p.y) == Approx(1.0).epsilon(1e-14));
      CHECK(p.z == Approx(v).margin(1e-15));
    }

  // Weight 0 at the centre: the control point (4, 1, 5) has no influence, z stays 0.
  const RationalBezierPatch& flat = scene.rational[1];
  CHECK(flat.at(1, 1) == glm::dvec4(0, 0, 0, 0));
  for (double u : {0.2, 0.5, 0.9}) CHECK(rationalPatchPoint(flat, u, 0.5).z == 0.0);
}

TEST_CASE("scene: points are row by row, i along u", "[io][scene]") {
  const Scene scene = parse(sceneWith(
      "{\"type\": \"bezier\", \"degree\": [1, 2], \"points\": [[0, 0, 0], [0, 1, 1], [0, 2, 2], "
      "[1, 0, 10], [1, 1, 11], [1, 2, 12]]}"));
  REQUIRE(scene.bezier.size() == 1);
  const BezierPatch& p = scene.bezier[0];
  CHECK(p.degreeU == 1);
  CHECK(p.degreeV == 2);
  for (int i = 0; i <= 1; ++i)
    for (int j = 0; j <= 2; ++j) CHECK(p.at(i, j) == glm::dvec3(i, j, 10 * i + j));
}

TEST_CASE("scene: CRLF, spacing, number spellings, comments and file order", "[io][scene]") {
  const std::string text =
      "\xEF\xBB\xBF{ \"comment\": [\"any JSON\", 1],\r\n"
      "\t\"surfaces\" : [\r\n" +
      bspline() +
      ",\r\n"
      "  {\"name\": \"second\", \"comment\": \"x\", \"type\": \"bezier\", \"degree\": [1, 1],\r\n"
      "   \"points\": [[1.5e-3, -0, 1E2], [0.25, 1e15, -1e15], [7, 8, 9], [10000, 2, 3]],\r\n"
      "   \"weights\": [1, 0.5, 2, 1e-3]}],\r\n"
      "\"tessera_scene\": 1}\r\n";
  const Scene scene = parse(text);
  REQUIRE(scene.order.size() == 2);
  CHECK(scene.order[0].type == SceneSurfaceType::BSpline);
  CHECK(scene.order[0].line == 3);
  CHECK(scene.order[1].type == SceneSurfaceType::Rational);
  CHECK(scene.order[1].line == 11);
  CHECK(scene.order[1].degreeLine == 11);
  CHECK(scene.order[1].weightsLine == 13);
  CHECK(scene.order[1].name == "second");
  const RationalBezierPatch& r = scene.rational[0];
  CHECK(r.cpw[0] == glm::dvec4(1.5e-3, 0, 100, 1));
  CHECK(r.cpw[1] == glm::dvec4(0.125, 5e14, -5e14, 0.5));
  CHECK(r.cpw[3].w == 1e-3);
  CHECK(scene.bsplines[0].knotsU[4] == 0.5);
}

TEST_CASE("scene: malformed JSON names the file, line and reason", "[io][scene]") {
  checkCases({
      {"empty.json", "", InputErrorKind::Syntax, 1, "invalid JSON at column 1: "},
      {"blank_lines.json", "\n\n  \n", InputErrorKind::Syntax, 4, "unexpected end of input"},
      {"truncated.json",
       "{\"tessera_scene\": 1, \"surfaces\": [\n{\"type\": \"bezier\", \"degree\": [1, 1],\n",
       InputErrorKind::Syntax, 3, "unexpected end of input"},
      {"truncated_in_array.json", "{\"tessera_scene\": 1, \"surfaces\": [\n" + bilinear() + ",\n[1,",
       InputErrorKind::Syntax, 5, "invalid JSON at column 4: "},
      {"trailing_comma.json", "{\"tessera_scene\": 1,\n \"surfaces\": [1, 2,]}",
       InputErrorKind::Syntax, 2, "invalid JSON at column 20: "},
      {"single_quotes.json", "{\"tessera_scene\": 1,\n\n 'surfaces': []}", InputErrorKind::Syntax,
       3, "invalid JSON at column 2: "},
      {"comment.json", "// a comment\n{\"tessera_scene\": 1}", InputErrorKind::Syntax, 1,
       "invalid JSON"},
      {"after_document.json", sceneWith(bilinear()) + "\n{}\n", InputErrorKind::Syntax, 7,
       "invalid JSON at column 1: "},
      {"raw_newline_in_string.json", "{\"tessera_scene\": 1, \"comment\": \"two\nlines\"}",
       InputErrorKind::Syntax, 1, "control character"},
      {"duplicate_key.json", "{\"tessera_scene\": 1,\n \"surfaces\": [],\n \"tessera_scene\": 1}",
       InputErrorKind::Syntax, 3, "duplicate key \"tessera_scene\" in the object that starts on line 1"},
      {"deep.json", std::string(100, '[') + std::string(100, ']'), InputErrorKind::Syntax, 1,
       "JSON nested deeper than 64 levels"},
  });
}

TEST_CASE("scene: wrong structure names the file, line and reason", "[io][scene]") {
  checkCases({
      {"top_level_array.json", "\n[1, 2]", InputErrorKind::Syntax, 2,
       "a scene is an object {\"tessera_scene\": 1, \"surfaces\": [...]}, found an array"},
      {"no_version.json", "{\n\"surfaces\": []}", InputErrorKind::Syntax, 1,
       "not a Tessera scene: the top-level object has no \"tessera_scene\" version"},
      {"wrong_version.json", "{\"surfaces\": [],\n \"tessera_scene\": 2}", InputErrorKind::Syntax,
       2, "unsupported scene version 2: this reader reads version 1"},
      {"version_string.json", "{\"tessera_scene\": \"1\"}", InputErrorKind::Syntax, 1,
       "unsupported scene version \"1\""},
      {"version_real.json", "{\"tessera_scene\": 1.5}", InputErrorKind::Syntax, 1,
       "unsupported scene version 1.5"},
      {"unknown_top_key.json", "{\"tessera_scene\": 1,\n \"surface\": []}", InputErrorKind::Syntax,
       2, "unknown key \"surface\" in the scene object (expected \"tessera_scene\", \"surfaces\""},
      {"no_surfaces.json", "{\"tessera_scene\": 1}", InputErrorKind::Syntax, 1,
       "the scene object has no \"surfaces\""},
      {"surfaces_object.json", "{\"tessera_scene\": 1,\n\"surfaces\": {}}", InputErrorKind::Syntax,
       2, "\"surfaces\" of the scene object must be an array, found an object"},
      {"surfaces_empty.json", "{\"tessera_scene\": 1,\n\"surfaces\": [\n]}", InputErrorKind::Count,
       2, "\"surfaces\" is empty: a scene needs at least one surface"},
      {"surface_not_object.json", sceneWith(bilinear() + ",\n 42"), InputErrorKind::Syntax, 5,
       "surface 2 must be an object, found a number"},
      {"no_type.json", sceneWith("{\"degree\": [1, 1]}"), InputErrorKind::Syntax, 2,
       "surface 1 has no \"type\""},
      {"unknown_type.json", sceneWith(bilinear() + ",\n{\n \"type\": \"nurbs\"}"),
       InputErrorKind::Syntax, 6,
       "unknown surface type \"nurbs\" (surface 2; expected \"bezier\" or \"bspline\")"},
      {"unknown_key.json", sceneWith(bilinear("[1, 1]", ",\n \"colour\": \"red\"")),
       InputErrorKind::Syntax, 3,
       "unknown key \"colour\" in surface 1 (expected \"type\", \"degree\", \"points\", "
       "\"weights\", \"name\", \"comment\")"},
      {"bspline_key_on_bezier.json", sceneWith(bilinear("[1, 1]", ", \"knots_u\": [0, 1]")),
       InputErrorKind::Syntax, 2, "unknown key \"knots_u\" in surface 1"},
      {"name_not_string.json", sceneWith("{\"type\": \"bezier\", \"name\": 7}"),
       InputErrorKind::Syntax, 2, "\"name\" of surface 1 must be a string, found a number"},
      {"no_points.json", sceneWith("{\"type\": \"bezier\",\n \"degree\": [1, 1]}"),
       InputErrorKind::Syntax, 2, "surface 1 has no \"points\""},
      {"degree_not_array.json", sceneWith(bilinear("3")), InputErrorKind::Syntax, 2,
       "\"degree\" of surface 1 must be an array, found a number"},
      {"degree_one_element.json", sceneWith(bilinear("[3]")), InputErrorKind::Syntax, 2,
       "\"degree\" of surface 1 must be [u, v] (two integers), found 1 elements"},
      {"degree_real.json", sceneWith(bilinear("[1,\n 2.5]")), InputErrorKind::Syntax, 3,
       "degree in v of surface 1 must be an integer, found 2.5"},
      {"degree_string.json", sceneWith(bilinear("[\"1\", 1]")), InputErrorKind::Syntax, 2,
       "degree in u of surface 1 must be a number, found a string"},
      {"point_not_array.json", sceneWith(bilinear("[1, 1]", "", "[0, 0, 0], 5,")),
       InputErrorKind::Syntax, 3, "point 2 of surface 1 must be [x, y, z], found a number"},
      {"point_two_coordinates.json",
       sceneWith(bilinear("[1, 1]", "", "[0, 0, 0], [0, 1, 0],", "[1, 0], [1, 1, 0]")),
       InputErrorKind::Syntax, 4, "point 3 of surface 1 must be [x, y, z], found an array of 2"},
      {"named_surface.json",
       sceneWith("{\"type\": \"bezier\", \"name\": \"lid\", \"degree\": [1, 1], \"points\": "
                 "[[0, 0, 0], [0, 1, 0], [1, 0, 0], [1, 1, true]]}"),
       InputErrorKind::Syntax, 2,
       "z of point 4 of surface 1 (\"lid\") must be a number, found a boolean"},
  });
}

TEST_CASE("scene: bad degrees, counts and numbers name the file, line and reason",
          "[io][scene]") {
  checkCases({
      {"degree_zero.json", sceneWith(bilinear("[0, 1]")), InputErrorKind::Degree, 2,
       "degree in u of surface 1 is 0; must be 1..7"},
      {"degree_eight.json", sceneWith(bilinear("[1,\n 8]")), InputErrorKind::Degree, 3,
       "degree in v of surface 1 is 8; must be 1..7"},
      {"degree_negative.json", sceneWith(bilinear("[-1, 1]")), InputErrorKind::Degree, 2,
       "degree in u of surface 1 is -1; must be 1..7"},
      {"degree_huge.json", sceneWith(bilinear("[99999999999, 1]")), InputErrorKind::Degree, 2,
       "degree in u of surface 1 is 99999999999"},
      {"too_few_points.json",
       sceneWith(bilinear("[1, 1]", "", "[0, 0, 0], [0, 1, 0],", "[1, 0, 0]")),
       InputErrorKind::Count, 3,
       "surface 1 has 3 points; degree [1, 1] (row by row, (n+1)(m+1)) needs 4"},
      {"too_many_points.json",
       sceneWith(bilinear("[1, 1]", "", "[0, 0, 0], [0, 1, 0],",
                          "[1, 0, 0], [1, 1, 0],\n [2, 2, 2]")),
       InputErrorKind::Count, 5, "surface 1 has 5 points; degree [1, 1]"},
      {"degree_mismatch.json", sceneWith(bilinear("[3, 3]")), InputErrorKind::Count, 3,
       "surface 1 has 4 points; degree [3, 3] (row by row, (n+1)(m+1)) needs 16"},
      {"not_a_number.json", sceneWith(bilinear("[1, 1]", "", "[0, 0, 0], [0, \"one\", 0],")),
       InputErrorKind::Syntax, 3, "y of point 2 of surface 1 must be a number, found a string"},
      {"null_coordinate.json", sceneWith(bilinear("[1, 1]", "", "[0, 0, 0], [0, 1, null],")),
       InputErrorKind::Syntax, 3, "z of point 2 of surface 1 must be a number, found null"},
      {"nan.json", sceneWith(bilinear("[1, 1]", "", "[0, 0, 0], [0, 1, 0],", "[NaN, 0, 0], [1, 1, 0]")),
       InputErrorKind::NonFinite, 4, "'NaN' is not a finite number"},
      {"nan_lowercase.json", sceneWith(bilinear("[1, 1]", "", "[nan, 0, 0], [0, 1, 0],")),
       InputErrorKind::NonFinite, 3, "'nan' is not a finite number"},
      {"nan_string.json", sceneWith(bilinear("[1, 1]", "", "[0, 0, 0], [0, 1, \"NaN\"],")),
       InputErrorKind::NonFinite, 3,
       "\"NaN\" is not a finite number (z of point 2 of surface 1)"},
      {"infinity.json",
       sceneWith(bilinear("[1, 1]", "", "[0, 0, 0], [0, 1, 0],", "[1, 0, 0], [1, Infinity, 0]")),
       InputErrorKind::NonFinite, 4, "'Infinity' is not a finite number"},
      {"minus_infinity.json", sceneWith(bilinear("[1, 1]", "", "[0, 0, 0],\n [0, -Infinity, 0],")),
       InputErrorKind::NonFinite, 4, "'-Infinity' is not a finite number"},
      {"inf_string.json", sceneWith(bilinear("[1, 1]", "", "[0, 0, \"-inf\"], [0, 1, 0],")),
       InputErrorKind::NonFinite, 3, "\"-inf\" is not a finite number (z of point 1"},
      {"huge.json", sceneWith(bilinear("[1, 1]", "", "[0, 0, 0], [0, 1, 0],", "[1, 1e300, 0], [1, 1, 0]")),
       InputErrorKind::Range, 4,
       "1e+300 exceeds the largest accepted magnitude 1e15 (y of point 3 of surface 1)"},
      {"just_over.json", sceneWith(bilinear("[1, 1]", "", "[0, 0, -1.0000001e15], [0, 1, 0],")),
       InputErrorKind::Range, 3, "exceeds the largest accepted magnitude 1e15 (z of point 1"},
      {"huge_integer.json", sceneWith(bilinear("[1, 1]", "", "[0, 0, 0], [0, 1, 10000000000000000000],")),
       InputErrorKind::Range, 3, "exceeds the largest accepted magnitude 1e15 (z of point 2"},
      {"overflow.json", sceneWith(bilinear("[1, 1]", "", "[0, 0, 0], [0, 1e400, 0],")),
       InputErrorKind::Range, 3, "'1e400' is outside the range of a double"},
  });
}

TEST_CASE("scene: bad weights name the file, line and reason", "[io][scene]") {
  auto withWeights = [](const std::string& weights) {
    return sceneWith(bilinear("[1, 1]", ",\n \"weights\": " + weights));
  };
  checkCases({
      {"negative_weight.json", withWeights("[1, 1,\n -0.5, 1]"), InputErrorKind::Weight, 4,
       "weight 3 of surface 1 is -0.5; weights must be ≥ 0"},
      {"all_zero_weights.json", withWeights("[0, 0, 0, 0]"), InputErrorKind::Weight, 3,
       "all weights of surface 1 are zero"},
      {"zero_corner_weight.json", withWeights("[1, 1, 1,\n 0]"), InputErrorKind::Weight, 4,
       "weight 4 of surface 1 (the corner b_1,1) is zero: the surface would be undefined at "
       "that corner"},
      {"too_few_weights.json", withWeights("[1, 1, 1]"), InputErrorKind::Count, 3,
       "surface 1 has 3 weights for 4 points"},
      {"weights_not_array.json", withWeights("1"), InputErrorKind::Syntax, 3,
       "\"weights\" of surface 1 must be an array, found a number"},
      {"nan_weight.json", withWeights("[1, NaN, 1, 1]"), InputErrorKind::NonFinite, 3,
       "'NaN' is not a finite number"},
      {"huge_weight.json", withWeights("[1, 1, 1, 2e15]"), InputErrorKind::Range, 3,
       "2e+15 exceeds the largest accepted magnitude 1e15 (weight 4 of surface 1)"},
      {"string_weight.json", withWeights("[1, 1, \"1\", 1]"), InputErrorKind::Syntax, 3,
       "weight 3 of surface 1 must be a number, found a string"},
  });
}

TEST_CASE("scene: bad B-spline surfaces name the file, line and reason", "[io][scene]") {
  // A valid one first, so the failures below are the knots' and counts' own.
  const Scene ok = parse(sceneWith(bspline()));
  REQUIRE(ok.bsplines.size() == 1);
  CHECK(ok.bsplines[0].at(4, 3) == glm::dvec3(4, 3, 0));

  checkCases({
      {"decreasing_knots.json", sceneWith(bspline("[0, 0, 0, 0.6,\n 0.5, 1, 1, 1, 1]")),
       InputErrorKind::Knots, 4,
       "knots_u: knots must be non-decreasing, but x_3 = 0.6 > x_4 = 0.5 (surface 1)"},
      {"wrong_knot_count.json", sceneWith(bspline("[0, 0, 0, 0, 0.5, 1, 1, 1, 1]", "[0, 0, 0, 1, 1, 1]")),
       InputErrorKind::Knots, 4,
       "knots_v: wrong length: expected 8 knots (4 control points + degree 3 + 1), got 6 "
       "(surface 1)"},
      {"knot_multiplicity.json", sceneWith(bspline("[0, 0, 0, 0, 0, 1, 1, 1, 1]")),
       InputErrorKind::Knots, 3, "knots_u: "},
      {"empty_knot_domain.json", sceneWith(bspline("[0, 0, 0, 0, 0, 0, 0, 0, 1]")),
       InputErrorKind::Knots, 3, "knots_u: "},
      {"nan_knot.json", sceneWith(bspline("[0, 0, 0, 0, NaN, 1, 1, 1, 1]")),
       InputErrorKind::NonFinite, 3, "'NaN' is not a finite number"},
      {"huge_knot.json", sceneWith(bspline("[0, 0, 0, 0, 0.5, 1, 1, 1, 1e16]")),
       InputErrorKind::Range, 3,
       "exceeds the largest accepted magnitude 1e15 (knot 9 of knots_u of surface 1)"},
      {"knots_not_array.json", sceneWith(bspline("\"uniform\"")), InputErrorKind::Syntax, 3,
       "\"knots_u\" of surface 1 must be an array, found a string"},
      {"count_too_small.json", sceneWith(bspline("[0, 1]", "[0, 1]", "[5, 3]")),
       InputErrorKind::Count, 2,
       "count in v of surface 1 is 3; degree 3 needs at least 4 control points"},
      {"count_points_mismatch.json", sceneWith(bspline("[0, 0, 0, 0, 0.5, 1, 1, 1, 1]",
                                                       "[0, 0, 0, 0, 0.5, 1, 1, 1, 1]", "[5, 5]")),
       InputErrorKind::Count, 5, "surface 1 has 20 points; count [5, 5] (row by row, nu·nv) needs 25"},
      {"count_huge.json", sceneWith(bspline("[0, 1]", "[0, 1]", "[5, 10000000000]")),
       InputErrorKind::Count, 2, "count in v of surface 1 is 10000000000; at most 1000000"},
      {"count_real.json", sceneWith(bspline("[0, 1]", "[0, 1]", "[5.0, 4]")),
       InputErrorKind::Syntax, 2, "count in u of surface 1 must be an integer, found 5.0"},
      {"no_count.json",
       sceneWith("{\"type\": \"bspline\", \"degree\": [3, 3],\n \"knots_u\": [], \"knots_v\": []}"),
       InputErrorKind::Syntax, 2, "surface 1 has no \"count\""},
      {"weights_on_bspline.json",
       sceneWith("{\"type\": \"bspline\", \"degree\": [3, 3],\n \"weights\": [1]}"),
       InputErrorKind::Syntax, 3, "unknown key \"weights\" in surface 1 (expected \"type\", "
                                  "\"degree\", \"count\", \"knots_u\", \"knots_v\", \"points\""},
  });
}

TEST_CASE("scene: files on disk", "[io][scene]") {
  SECTION("a missing file is an Io error naming it") {
    const InputError e =
        test::inputErrorOf([] { readScene("/nonexistent/dir/scene.json"); }, "a missing file");
    CHECK(e.kind() == InputErrorKind::Io);
    CHECK(e.file() == "/nonexistent/dir/scene.json");
    CHECK(e.line() == 0);
    CHECK(std::string(e.what()).find("cannot open for reading") != std::string::npos);
  }
  SECTION("a directory is an Io error") {
    const InputError e =
        test::inputErrorOf([] { readScene(TESSERA_SOURCE_DIR "/data"); }, "a directory");
    CHECK(e.kind() == InputErrorKind::Io);
    CHECK(std::string(e.what()).find("is a directory, not a .json scene file") !=
          std::string::npos);
  }
  SECTION("the bad inputs kept as files") {
    struct FileCase {
      const char* file;
      InputErrorKind kind;
      int line;
      const char* reason;
    };
    const FileCase cases[] = {
        {"truncated.json", InputErrorKind::Syntax, 10, "unexpected end of input"},
        {"negative_weight.json", InputErrorKind::Weight, 13,
         "weight 4 of surface 1 (\"bent quad\") is -1; weights must be ≥ 0"},
        {"decreasing_knots.json", InputErrorKind::Knots, 8,
         "knots_v: knots must be non-decreasing, but x_4 = 1 > x_5 = 0.5"},
    };
    for (const FileCase& c : cases) {
      const std::string path = std::string(TESSERA_SOURCE_DIR "/tests/bad_inputs/") + c.file;
      INFO(path);
      try {
        readScene(path);
        FAIL("no error");
      } catch (const InputError& e) {
        INFO(e.what());
        CHECK(e.kind() == c.kind);
        CHECK(e.file() == path);
        CHECK(e.line() == c.line);
        CHECK(std::string(e.what()).find(c.reason) != std::string::npos);
      }
    }
  }
}
