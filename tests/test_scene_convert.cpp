// Scenes to patches (host/io/scene_convert.h): degree elevation and B-spline pieces give the same
// surfaces, surfaces stay in file order, degrees above 3 and rational weights are kept (a
// bad weight in a scene built in code is an InputError naming the surface), and the example
// scenes go through readSurfaceFile and the CPU backend to a mesh.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "geometry/bezier.h"
#include "bspline/bspline.h"
#include "bspline/to_bezier.h"
#include "io/errors.h"
#include "geometry/rational.h"
#include "io/scene_reader.h"
#include "io/surface_reader.h"
#include "bspline/knots.h"
#include "io/scene_convert.h"
#include "mesh/tessellate.h"

using namespace tessera;

namespace {

Scene parse(const std::string& text, const std::string& name = "convert.json") {
  std::istringstream in(text);
  return parseScene(in, name);
}

double maxAbs(const glm::dvec3& d) {
  return std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
}

// Largest difference between a bicubic patch and `reference(u, v)` on an 11 × 11 grid.
template <typename Reference>
double maxDeviation(const BezierPatch& patch, Reference reference) {
  double worst = 0.0;
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 10; ++j) {
      const double u = i / 10.0, v = j / 10.0;
      worst = std::max(worst, maxAbs(patchPoint(patch, u, v) - reference(u, v)));
    }
  return worst;
}

// A Bézier surface of the given degrees as scene JSON (points z = i·j, for variety), with
// "degree" on a line of its own.
std::string bezierJson(int n, int m, const std::string& extra = "") {
  std::string points;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j)
      points += (points.empty() ? "[" : ", [") + std::to_string(i) + ", " + std::to_string(j) +
                ", " + std::to_string(i * j % 3) + "]";
  return "{\"type\": \"bezier\",\n \"degree\": [" + std::to_string(n) + ", " + std::to_string(m) +
         "],\n \"points\": [" + points + "]" + extra + "}";
}

std::string sceneJson(const std::vector<std::string>& surfaces) {
  std::string text = "{\"tessera_scene\": 1, \"surfaces\": [\n";
  for (size_t k = 0; k < surfaces.size(); ++k) text += (k ? ",\n" : "") + surfaces[k];
  return text + "\n]}\n";
}

InputError convertError(const Scene& scene) {
  try {
    sceneToPatches(scene);
  } catch (const InputError& e) {
    return e;
  }
  FAIL("no InputError");
  throw std::logic_error("unreachable");
}

}  // namespace

TEST_CASE("convert: the example scene gives the same surfaces as bicubic patches",
          "[io][convert]") {
  const Scene scene = readScene(TESSERA_SOURCE_DIR "/data/scene_example.json");
  const std::vector<BezierPatch> patches = sceneToPatches(scene);
  // Bump (1), saddle (1), wave: 2 u-spans × 1 v-span.
  REQUIRE(patches.size() == 4);
  for (const BezierPatch& p : patches) {
    CHECK(p.degreeU == 3);
    CHECK(p.degreeV == 3);
    CHECK(p.cp.size() == 16);
  }
  CHECK(patches[0].cp == scene.bezier[0].cp);  // already bicubic: unchanged
  CHECK(maxDeviation(patches[1], [&](double u, double v) {
          return patchPoint(scene.bezier[1], u, v);
        }) < 1e-12);
  const BSplineSurface& wave = scene.bsplines[0];
  const std::vector<BezierPatchPiece> pieces = bezierPatches(wave);
  REQUIRE(pieces.size() == 2);
  for (size_t k = 0; k < pieces.size(); ++k) {
    const BezierPatchPiece& piece = pieces[k];
    CHECK(maxDeviation(patches[2 + k], [&](double s, double r) {
            return surfacePoint(wave, piece.u0 + s * (piece.u1 - piece.u0),
                                piece.v0 + r * (piece.v1 - piece.v0));
          }) < 1e-12);
  }
}

TEST_CASE("convert: B-spline surfaces become one bicubic patch per span pair",
          "[io][convert]") {
  // Quadratic × linear, 6 × 3 control points, a double interior knot in u: u-spans 4
  // ([0,.2], [.2,.5], [.5,.7]... see knots), v-spans 2; degree-elevated to bicubic.
  BSplineSurface s;
  s.degreeU = 2;
  s.degreeV = 1;
  s.countU = 6;
  s.countV = 3;
  s.knotsU = {0, 0, 0, 0.2, 0.5, 0.5, 1, 1, 1};
  s.knotsV = {0, 0, 0.3, 1, 1};
  for (int i = 0; i < s.countU; ++i)
    for (int j = 0; j < s.countV; ++j)
      s.cp.push_back(glm::dvec3(i, j, std::sin(0.7 * i + 1.3 * j)));
  validateSurface(s);
  Scene scene;
  scene.bsplines.push_back(s);
  const std::vector<BezierPatch> patches = sceneToPatches(scene);
  const std::vector<BezierPatchPiece> pieces = bezierPatches(s);
  // u-spans [0, .2], [.2, .5], [.5, 1]; v-spans [0, .3], [.3, 1].
  REQUIRE(pieces.size() == 6);
  REQUIRE(patches.size() == 6);
  for (size_t k = 0; k < pieces.size(); ++k) {
    INFO("piece " << k);
    const BezierPatchPiece& piece = pieces[k];
    CHECK(patches[k].degreeU == 3);
    CHECK(patches[k].degreeV == 3);
    CHECK(maxDeviation(patches[k], [&](double a, double b) {
            return surfacePoint(s, piece.u0 + a * (piece.u1 - piece.u0),
                                piece.v0 + b * (piece.v1 - piece.v0));
          }) < 1e-12);
  }
}

TEST_CASE("convert: surfaces stay in file order; equal weights are polynomial",
          "[io][convert]") {
  const std::string bspline =
      "{\"type\": \"bspline\", \"degree\": [1, 1], \"count\": [3, 2], \"knots_u\": [0, 0, 0.5, "
      "1, 1], \"knots_v\": [0, 0, 1, 1], \"points\": [[0, 0, 0], [0, 1, 0], [1, 0, 1], [1, 1, 1], "
      "[2, 0, 0], [2, 1, 0]]}";
  const Scene scene = parse(sceneJson(
      {bspline, bezierJson(1, 2, ", \"weights\": [2, 2, 2, 2, 2, 2]"), bezierJson(2, 1)}));
  REQUIRE(scene.order.size() == 3);
  const std::vector<BezierPatch> patches = sceneToPatches(scene);
  REQUIRE(patches.size() == 4);  // 2 B-spline pieces, then the rational, then the Bézier
  CHECK(patches[0].at(0, 0) == glm::dvec3(0, 0, 0));
  CHECK(patches[1].at(3, 3) == glm::dvec3(2, 1, 0));
  const RationalBezierPatch& rational = scene.rational[0];
  CHECK(maxDeviation(patches[2], [&](double u, double v) {
          BezierPatch plain;
          plain.degreeU = rational.degreeU;
          plain.degreeV = rational.degreeV;
          for (const glm::dvec4& p : rational.cpw) plain.cp.push_back(glm::dvec3(p) / p.w);
          return patchPoint(plain, u, v);
        }) < 1e-12);
  CHECK(patches[2].at(1, 0).z == 0.0);
  CHECK(maxDeviation(patches[3], [&](double u, double v) {
          return patchPoint(scene.bezier[0], u, v);
        }) < 1e-12);
}

TEST_CASE("convert: degrees above 3 stay as they are, rational weights are kept",
          "[io][convert]") {
  SECTION("a degree 5×4 patch is passed on unchanged, lower degrees become bicubic") {
    const Scene scene = parse(sceneJson({bezierJson(3, 3), bezierJson(2, 2), bezierJson(5, 4)}));
    const std::vector<BezierPatch> patches = sceneToPatches(scene);
    REQUIRE(patches.size() == 3);
    CHECK((patches[1].degreeU == 3 && patches[1].degreeV == 3));
    CHECK((patches[2].degreeU == 5 && patches[2].degreeV == 4));
    CHECK(patches[2].cp == scene.bezier[2].cp);
    CHECK(patches[2].weights.empty());
  }
  SECTION("a quartic B-spline becomes quartic Bézier pieces") {
    const Scene scene = parse(sceneJson(
        {"{\"type\": \"bspline\", \"name\": \"quartic\",\n \"degree\": [4, 1], \"count\": [5, 2], "
         "\"knots_u\": [0, 0, 0, 0, 0, 1, 1, 1, 1, 1], \"knots_v\": [0, 0, 1, 1], \"points\": "
         "[[0, 0, 0], [0, 1, 0], [1, 0, 1], [1, 1, 0], [2, 0, 0], [2, 1, 0], [3, 0, 0], "
         "[3, 1, 0], [4, 0, 0], [4, 1, 0]]}"}));
    const std::vector<BezierPatch> patches = sceneToPatches(scene);
    REQUIRE(patches.size() == 1);
    CHECK((patches[0].degreeU == 4 && patches[0].degreeV == 1));
    CHECK(maxDeviation(patches[0], [&](double u, double v) {
            return surfacePoint(scene.bsplines[0], u, v);
          }) < 1e-12);
  }
  SECTION("a rational patch keeps its points and weights: the same surface") {
    const Scene scene = parse(sceneJson({bezierJson(2, 2, ",\n \"weights\": [1, 2, 1, 2, 0, 2, 1, 2, 1]")}));
    const std::vector<BezierPatch> patches = sceneToPatches(scene);
    REQUIRE(patches.size() == 1);
    REQUIRE(patches[0].weights.size() == 9);
    CHECK(patches[0].weights[4] == 0.0);
    CHECK(maxDeviation(patches[0], [&](double u, double v) {
            return rationalPatchPoint(scene.rational[0], u, v);
          }) < 1e-12);
  }
  SECTION("a scene built in code with a zero corner weight names the surface") {
    Scene scene;
    RationalBezierPatch bad;
    bad.degreeU = bad.degreeV = 1;
    bad.cpw = {{0, 0, 0, 1}, {0, 1, 0, 2}, {1, 0, 0, 1}, {0, 0, 0, 0}};
    scene.rational.push_back(bad);
    const InputError e = convertError(scene);
    CHECK(e.kind() == InputErrorKind::Weight);
    CHECK(std::string(e.what()) == "scene: surface 1 has a corner weight that is not positive");
  }
}

TEST_CASE("convert: the example scene tessellates through readSurfaceFile on the CPU",
          "[io][convert]") {
  const std::vector<BezierPatch> patches =
      readSurfaceFile(TESSERA_SOURCE_DIR "/data/scene_example.json");
  REQUIRE(patches.size() == 4);
  Backend backend = makeMirrorBackend();
  QuadtreeOptions options;
  const Tessellation t = tessellate(patches, options, backend);
  CHECK(t.mesh.triangleCount() > 0);
  CHECK(t.mesh.vertexCount() > 0);
  CHECK_NOTHROW(t.mesh.validate());
  // Every patch produced triangles.
  std::vector<bool> seen(patches.size(), false);
  for (uint32_t patch : t.trianglePatch) seen.at(patch) = true;
  CHECK(std::all_of(seen.begin(), seen.end(), [](bool s) { return s; }));
}

TEST_CASE("convert: the rational example tessellates through readSurfaceFile on the CPU",
          "[io][convert]") {
  const std::vector<BezierPatch> patches =
      readSurfaceFile(TESSERA_SOURCE_DIR "/data/scene_rational.json");
  REQUIRE(patches.size() == 2);
  REQUIRE(patches[0].weights.size() == 6);
  REQUIRE(patches[1].weights.size() == 9);
  Backend backend = makeMirrorBackend();
  const Tessellation t = tessellate(patches, QuadtreeOptions(), backend);
  CHECK(t.mesh.triangleCount() > 0);
  CHECK_NOTHROW(t.mesh.validate());
  // The quarter cylinder's vertices lie on x² + y² = 1.
  double worst = 0;
  for (size_t k = 0; k < t.mesh.positions.size(); ++k)
    if (t.mesh.patchIds[k] == 0)
      worst = std::max(worst, std::fabs(std::hypot(double(t.mesh.positions[k].x),
                                                    double(t.mesh.positions[k].y)) - 1.0));
  WARN("scene_rational.json: " << t.mesh.triangleCount() << " triangles; quarter cylinder "
       "vertices off the unit cylinder by at most " << worst);
  CHECK(worst < 1e-6);
}
