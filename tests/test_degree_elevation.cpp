// Degree elevation (host/geometry/degree_elevation.h): the elevated patch is the same surface, end
// rows and columns are kept, and a boundary shared in opposite directions stays bit-identical.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "geometry/bezier.h"
#include "geometry/degree_elevation.h"

using namespace tessera;

namespace {

BezierPatch randomPatch(int degreeU, int degreeV, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coord(-2.0, 2.0);
  BezierPatch p;
  p.degreeU = degreeU;
  p.degreeV = degreeV;
  p.cp.resize(static_cast<size_t>((degreeU + 1) * (degreeV + 1)));
  for (auto& q : p.cp) q = glm::dvec3(coord(rng), coord(rng), coord(rng));
  return p;
}

// Largest coordinate difference between the two patches over an 11 × 11 grid and a few
// points just outside [0, 1]² (the polynomials must agree everywhere, not only inside).
double maxDeviation(const BezierPatch& a, const BezierPatch& b) {
  double worst = 0.0;
  auto at = [&](double u, double v) {
    const glm::dvec3 d = patchPoint(a, u, v) - patchPoint(b, u, v);
    worst = std::max({worst, std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
  };
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 10; ++j) at(i / 10.0, j / 10.0);
  at(-0.1, 0.3);
  at(1.2, -0.05);
  return worst;
}

}  // namespace

TEST_CASE("elevation: a straight segment gets evenly spaced points", "[io][elevation]") {
  BezierPatch line;
  line.degreeU = 1;
  line.degreeV = 1;
  line.cp = {{0, 0, 0}, {0, 3, 0}, {3, 0, 0}, {3, 3, 0}};
  const BezierPatch cubic = elevateDegreeTo(line, 3, 3);
  REQUIRE(cubic.degreeU == 3);
  REQUIRE(cubic.degreeV == 3);
  REQUIRE(cubic.cp.size() == 16);
  // b'_i = (i/(n+1)) b_{i-1} + (1 − i/(n+1)) b_i on (0, 3): (0, 1.5, 3), then (0, 1, 2, 3)
  // up to the rounding of 1/3 and 2/3.
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; j <= 3; ++j) {
      CHECK(cubic.at(i, j).x == Approx(i).margin(1e-15));
      CHECK(cubic.at(i, j).y == Approx(j).margin(1e-15));
      CHECK(cubic.at(i, j).z == 0.0);
    }
}

TEST_CASE("elevation: one step in u or v is the same surface", "[io][elevation]") {
  unsigned seed = 1;
  for (int n = 1; n < kMaxDegree; ++n)
    for (int m = 1; m < kMaxDegree; ++m) {
      INFO("degree " << n << "x" << m);
      const BezierPatch p = randomPatch(n, m, seed++);
      const BezierPatch u = elevateDegreeU(p);
      const BezierPatch v = elevateDegreeV(p);
      CHECK(u.degreeU == n + 1);
      CHECK(u.degreeV == m);
      CHECK(v.degreeU == n);
      CHECK(v.degreeV == m + 1);
      CHECK(maxDeviation(p, u) < 1e-12);
      CHECK(maxDeviation(p, v) < 1e-12);
      // Corners exactly; the end rows of an elevation along u are the old ones exactly.
      CHECK(u.at(0, 0) == p.at(0, 0));
      CHECK(u.at(n + 1, m) == p.at(n, m));
      for (int j = 0; j <= m; ++j) {
        CHECK(u.at(0, j) == p.at(0, j));
        CHECK(u.at(n + 1, j) == p.at(n, j));
      }
      for (int i = 0; i <= n; ++i) {
        CHECK(v.at(i, 0) == p.at(i, 0));
        CHECK(v.at(i, m + 1) == p.at(i, m));
      }
    }
}

TEST_CASE("elevation: every degree up to bicubic evaluates identically", "[io][elevation]") {
  for (int n = 1; n <= 3; ++n)
    for (int m = 1; m <= 3; ++m) {
      INFO("degree " << n << "x" << m);
      const BezierPatch p = randomPatch(n, m, 100u + static_cast<unsigned>(4 * n + m));
      const BezierPatch cubic = elevateDegreeTo(p, 3, 3);
      CHECK(cubic.degreeU == 3);
      CHECK(cubic.degreeV == 3);
      CHECK(maxDeviation(p, cubic) < 1e-12);
    }
  const BezierPatch p = randomPatch(2, 1, 7);
  CHECK(maxDeviation(p, elevateDegreeTo(p, 7, 7)) < 1e-12);
}

TEST_CASE("elevation: a boundary elevated in either direction is bit-identical",
          "[io][elevation]") {
  // Reverse the patch along u: its rows, hence every column curve, run the other way.
  const BezierPatch p = randomPatch(2, 2, 42);
  BezierPatch reversed = p;
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j) reversed.at(i, j) = p.at(2 - i, j);
  const BezierPatch a = elevateDegreeTo(p, 3, 3);
  const BezierPatch b = elevateDegreeTo(reversed, 3, 3);
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; j <= 3; ++j) CHECK(a.at(i, j) == b.at(3 - i, j));
}

TEST_CASE("elevation: impossible requests throw", "[io][elevation]") {
  CHECK_THROWS_AS(elevateDegreeU(randomPatch(kMaxDegree, 1, 3)), std::invalid_argument);
  CHECK_THROWS_AS(elevateDegreeV(randomPatch(1, kMaxDegree, 3)), std::invalid_argument);
  CHECK_THROWS_AS(elevateDegreeTo(randomPatch(3, 3, 3), 2, 3), std::invalid_argument);
  CHECK_THROWS_AS(elevateDegreeTo(randomPatch(3, 3, 3), 3, 8), std::invalid_argument);
  BezierPatch broken = randomPatch(2, 2, 3);
  broken.cp.pop_back();
  CHECK_THROWS_AS(elevateDegreeU(broken), std::invalid_argument);
}
