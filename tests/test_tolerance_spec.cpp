// Rule T's tolerance as users give it (host/quadtree/tolerance.h): model units or a percentage
// of the control points' bounding-box diagonal, bad values refused with the text named; and
// the public API's relativeTolerance agreeing with it.
#include <tessera/tessera.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "io/bpt_reader.h"
#include "quadtree/tolerance.h"

using namespace tessera;

TEST_CASE("tolerance: model units and percentages parse; bad values are refused", "[tolerance]") {
  const ToleranceSpec absolute = parseTolerance("0.01");
  REQUIRE_FALSE(absolute.relative);
  REQUIRE(absolute.value == 0.01);
  const ToleranceSpec percent = parseTolerance("0.1%");
  REQUIRE(percent.relative);
  REQUIRE(percent.value == 0.1 / 100);
  REQUIRE(parseTolerance("100%").value == 1.0);
  REQUIRE(parseTolerance("2e-3").value == 2e-3);
  const ToleranceSpec pixels = parseTolerance("0.5px");
  REQUIRE(pixels.pixels);
  REQUIRE_FALSE(pixels.relative);
  REQUIRE(pixels.value == 0.5);
  REQUIRE_THROWS_WITH(resolveTolerance(pixels, {}), Catch::Contains("needs a camera"));
  for (const char* bad : {"0", "-0.01", "nan", "inf", "abc", "abc%", "%", "", "0%", "-1%",
                          "150%", "100.5%", "0.01x", " 0.01", "0.1%%", "nan%", "0px", "-1px",
                          "px", "1 px", "infpx", "1%px", "1pxx"}) {
    INFO("'" << bad << "'");
    REQUIRE_THROWS_AS(parseTolerance(bad), std::invalid_argument);
    REQUIRE_THROWS_WITH(parseTolerance(bad), Catch::Contains(std::string("'") + bad + "'"));
  }
}

TEST_CASE("tolerance: a percentage is of the diagonal of all control points", "[tolerance]") {
  // Two unit-square bilinear patches side by side: the box is 2 × 1 × 0.
  BezierPatch a;
  a.degreeU = a.degreeV = 1;
  a.cp = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}};
  BezierPatch b = a;
  for (glm::dvec3& p : b.cp) p.x += 1;
  REQUIRE(controlPointDiagonal({a, b}) == std::sqrt(5.0));
  REQUIRE(resolveTolerance(parseTolerance("1%"), {a, b}) == 0.01 * std::sqrt(5.0));
  REQUIRE(resolveTolerance(parseTolerance("0.25"), {a, b}) == 0.25);
  // A weight-0 point (a direction, not a place) does not count; here it lies far out.
  BezierPatch rational = b;
  rational.weights = {1, 0, 1, 1};
  rational.cp[1] = {100, 100, 100};
  REQUIRE(controlPointDiagonal({a, rational}) == std::sqrt(5.0));
  // A model of size 0 has no relative tolerance.
  BezierPatch point = a;
  for (glm::dvec3& p : point.cp) p = {3, 3, 3};
  REQUIRE_THROWS_AS(controlPointDiagonal({point}), std::invalid_argument);
  REQUIRE_THROWS_AS(controlPointDiagonal({}), std::invalid_argument);

  const std::vector<BezierPatch> teapot = readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt");
  const double diagonal = controlPointDiagonal(teapot);
  WARN("teapot: control-point diagonal " << diagonal << ", default tolerance "
                                         << kDefaultRelativeTolerance * diagonal);
  REQUIRE(diagonal > 5);  // the teapot spans about 6.4 × 3.2 × 3.15
  REQUIRE(diagonal < 10);
}

TEST_CASE("public API: relativeTolerance is the fraction of boundingBoxDiagonal", "[api][tolerance]") {
  const std::vector<tessera::Patch> patches =
      tessera::loadPatches(TESSERA_SOURCE_DIR "/data/teapot.bpt");
  const double diagonal = tessera::boundingBoxDiagonal(patches);
  REQUIRE(diagonal == controlPointDiagonal(readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt")));
  REQUIRE(tessera::relativeTolerance(patches, 0.001) == 0.001 * diagonal);
  for (double bad : {0.0, -0.1, 1.5, std::nan("")})
    REQUIRE_THROWS_AS(tessera::relativeTolerance(patches, bad), tessera::ArgumentError);
  REQUIRE_THROWS_AS(tessera::boundingBoxDiagonal({}), tessera::ArgumentError);

  // The uniform grids by name, and their options checked.
  tessera::Tessellator tessellator({tessera::Device::Cpu});
  tessera::ToleranceOptions uniform;
  uniform.method = tessera::ToleranceMethod::UniformGrids;
  uniform.maxPerDirection = 64;
  const tessera::Mesh mesh = tessellator.tessellateToTolerance(patches, 0.01, uniform);
  REQUIRE(mesh.triangleCount() > 0);
  uniform.maxPerDirection = 0;
  REQUIRE_THROWS_AS(tessellator.tessellateToTolerance(patches, 0.01, uniform),
                    tessera::ArgumentError);
  uniform.maxPerDirection = 64;
  uniform.maxNodes = 10;
  REQUIRE_THROWS_AS(tessellator.tessellateToTolerance(patches, 0.01, uniform),
                    tessera::LimitError);
}
