// side_fold.h: a side whose control points lie on a line and turn back is a fold; the images of
// a point are the other strand's points at the same place on the line.
#include <catch2/catch.hpp>

#include <cmath>

#include "mesh/side_fold.h"

using namespace tessera;

TEST_CASE("a side that doubles back on its line is a fold with exact images", "[watertight]") {
  // The teaspoon's handle tip (patch 12, u = 1): x = −a, +a, 0, 0 at constant y, z, so
  // x' = 6a(1−t)(1−2t): it turns at t = 1/2, where x = a/4.
  const double a = 0.000357143;
  const std::vector<glm::dvec3> tip = {
      {-a, -1, 0.0178571}, {a, -1, 0.0178571}, {0, -1, 0.0178571}, {0, -1, 0.0178571}};
  const auto fold = findSideFold(tip);
  REQUIRE(fold);
  REQUIRE(fold->strands.size() == 3);
  CHECK(std::fabs(fold->strands[1] - 0.5) < 1e-12);
  double worst = 0;
  for (double t : {0.3, 0.45, 0.6, 0.9, 1.0}) {
    const double s = foldCoordinate(*fold, t);
    const std::vector<double> images = foldImages(*fold, t, s);
    REQUIRE(images.size() == 1);
    CHECK((images[0] < 0.5) == (t > 0.5));  // on the other strand
    worst = std::max(worst, std::fabs(foldCoordinate(*fold, images[0]) - s));
  }
  WARN("largest |s(image) − s(t)|: " << worst);
  CHECK(worst <= 1e-15);
  // The part of the first strand the second does not retrace (x < 0, t < 1/4) has no image.
  CHECK(foldImages(*fold, 0.1, foldCoordinate(*fold, 0.1)).empty());
}

TEST_CASE("monotone, bent and collapsed sides are no folds", "[watertight]") {
  CHECK_FALSE(findSideFold({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}));
  CHECK_FALSE(findSideFold({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {1, 0, 0}}));  // not on one line
  CHECK_FALSE(findSideFold({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}}));
  // A polygon that goes back while the curve does not: x = 0, 2, 1, 3 has
  // x' = 3(2(1−t)² − 2t(1−t) + 2t²) > 0 everywhere.
  CHECK_FALSE(findSideFold({{0, 0, 0}, {2, 0, 0}, {1, 0, 0}, {3, 0, 0}}));
}
