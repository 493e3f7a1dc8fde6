// Data interpolation of grid points by bicubic Bézier patches (host/geometry/grid_interpolation.h) and
// the .grid reader (host/io/grid_reader.h): the patches interpolate, reproduce planes and
// bicubic polynomials, share their edges bit for bit and join C¹ (C², in fact); the bundled
// data sets load; malformed files are rejected naming file, line and reason.
#include <catch2/catch.hpp>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "geometry/grid_interpolation.h"
#include "io/errors.h"
#include "io/grid_reader.h"

using namespace tessera;
using Catch::Matchers::Contains;

namespace {

const std::string kDataDir = std::string(TESSERA_SOURCE_DIR) + "/data/";
const char* const kDataSets[] = {"grid_hill.grid", "grid_ridge.grid", "grid_bumps.grid"};

// A bicubic evaluator of its own, so these tests do not depend on the kernel under test
// elsewhere. Derivative orders (du, dv) ≤ 2 each.
double bernstein3(int k, double t, int derivative) {
  // Derivatives of B_k,3 by the difference formula: d/dt B_k,n = n (B_(k-1),(n-1) - B_k,(n-1)).
  const double s = 1.0 - t;
  switch (derivative) {
    case 0: {
      const double b[4] = {s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t};
      return b[k];
    }
    case 1: {
      const double b[4] = {-3 * s * s, 3 * s * s - 6 * t * s, 6 * t * s - 3 * t * t, 3 * t * t};
      return b[k];
    }
    default: {
      const double b[4] = {6 * s, -12 * s + 6 * t, 6 * s - 12 * t, 6 * t};
      return b[k];
    }
  }
}

glm::dvec3 evaluate(const BezierPatch& p, double u, double v, int du = 0, int dv = 0) {
  glm::dvec3 sum(0.0);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) sum += bernstein3(i, u, du) * bernstein3(j, v, dv) * p.at(i, j);
  return sum;
}

GridData makeGrid(int rows, int cols, const std::function<glm::dvec3(int, int)>& point) {
  GridData grid{rows, cols, {}};
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) grid.points.push_back(point(i, j));
  return grid;
}

// Irregular points in a box, fixed seed.
GridData randomGrid(int rows, int cols, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  return makeGrid(rows, cols, [&](int i, int j) {
    return glm::dvec3(-1.0 + 2.0 * i / (rows - 1) + 0.2 * jitter(rng),
                      -1.0 + 2.0 * j / (cols - 1) + 0.2 * jitter(rng), jitter(rng));
  });
}

std::vector<std::pair<std::string, GridData>> testGrids() {
  std::vector<std::pair<std::string, GridData>> grids;
  for (const char* name : kDataSets) grids.emplace_back(name, readGrid(kDataDir + name));
  grids.emplace_back("random 5x7", randomGrid(5, 7, 12345));
  grids.emplace_back("random 4x4", randomGrid(4, 4, 777));
  grids.emplace_back("random 3x6", randomGrid(3, 6, 99));
  grids.emplace_back("random 2x5", randomGrid(2, 5, 4242));
  return grids;
}

bool sameBits(const glm::dvec3& a, const glm::dvec3& b) {
  return std::memcmp(&a, &b, sizeof(glm::dvec3)) == 0;
}

double maxAbs(const glm::dvec3& a) {
  return std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)});
}

}  // namespace

TEST_CASE("splineTangents: not-a-knot slopes reproduce cubics; 2 points give the chord, "
          "3 the parabola",
          "[grid]") {
  for (int count = 2; count <= 9; ++count) {
    // x is linear, y as curved as the count allows, z a full cubic once count ≥ 4.
    const int degree = std::min(count - 1, 3);
    auto f = [&](double t) {
      return glm::dvec3(0.5 - 0.25 * t, degree >= 2 ? 0.3 * t * t - t : 2.0 * t,
                        degree >= 3 ? 0.1 * t * t * t - 0.4 * t * t + t - 1.0 : -t);
    };
    auto df = [&](double t) {
      return glm::dvec3(-0.25, degree >= 2 ? 0.6 * t - 1.0 : 2.0,
                        degree >= 3 ? 0.3 * t * t - 0.8 * t + 1.0 : -1.0);
    };
    std::vector<glm::dvec3> y;
    for (int k = 0; k < count; ++k) y.push_back(f(k));
    const std::vector<glm::dvec3> m = splineTangents(y);
    REQUIRE(m.size() == y.size());
    for (int k = 0; k < count; ++k) {
      INFO("count " << count << ", node " << k);
      CHECK(maxAbs(m[k] - df(k)) <= 1e-12);
    }
  }
  CHECK_THROWS_AS(splineTangents({glm::dvec3(1.0)}), std::invalid_argument);
  CHECK_THROWS_AS(splineTangents({}), std::invalid_argument);
}

TEST_CASE("splineTangents: the spline is C² with not-a-knot ends on arbitrary data", "[grid]") {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  for (int count : {4, 5, 8, 13}) {
    std::vector<glm::dvec3> y(count);
    for (auto& p : y) p = glm::dvec3(value(rng), value(rng), value(rng));
    const std::vector<glm::dvec3> m = splineTangents(y);
    // Second and third derivatives of the Hermite cubic on [k, k+1] at its ends.
    auto d2Start = [&](int k) { return -6.0 * y[k] + 6.0 * y[k + 1] - 4.0 * m[k] - 2.0 * m[k + 1]; };
    auto d2End = [&](int k) { return 6.0 * y[k] - 6.0 * y[k + 1] + 2.0 * m[k] + 4.0 * m[k + 1]; };
    auto d3 = [&](int k) { return 12.0 * y[k] - 12.0 * y[k + 1] + 6.0 * m[k] + 6.0 * m[k + 1]; };
    for (int k = 1; k + 1 < count; ++k) {
      INFO("count " << count << ", knot " << k);
      CHECK(maxAbs(d2End(k - 1) - d2Start(k)) <= 1e-12);
    }
    INFO("count " << count);
    CHECK(maxAbs(d3(0) - d3(1)) <= 1e-12);
    CHECK(maxAbs(d3(count - 3) - d3(count - 2)) <= 1e-12);
  }
}

TEST_CASE("interpolateGrid: one patch per cell in row-major order, through every grid point",
          "[grid]") {
  for (const auto& [name, grid] : testGrids()) {
    INFO(name);
    const std::vector<BezierPatch> patches = interpolateGrid(grid);
    REQUIRE(patches.size() == static_cast<size_t>((grid.rows - 1) * (grid.cols - 1)));
    for (int i = 0; i + 1 < grid.rows; ++i) {
      for (int j = 0; j + 1 < grid.cols; ++j) {
        const BezierPatch& p = patches[i * (grid.cols - 1) + j];
        REQUIRE(p.degreeU == 3);
        REQUIRE(p.degreeV == 3);
        REQUIRE(p.cp.size() == 16);
        INFO("cell " << i << ", " << j);
        CHECK(maxAbs(p.at(0, 0) - grid.at(i, j)) <= 1e-12);
        CHECK(maxAbs(p.at(3, 0) - grid.at(i + 1, j)) <= 1e-12);
        CHECK(maxAbs(p.at(0, 3) - grid.at(i, j + 1)) <= 1e-12);
        CHECK(maxAbs(p.at(3, 3) - grid.at(i + 1, j + 1)) <= 1e-12);
        // The surface itself, not only the net, passes through the corners.
        CHECK(maxAbs(evaluate(p, 1.0, 1.0) - grid.at(i + 1, j + 1)) <= 1e-12);
      }
    }
  }
}

TEST_CASE("interpolateGrid: points on a plane give patches whose control points all lie on it",
          "[grid]") {
  // A tilted plane; the points are spread irregularly over it, so tangents and twists are far
  // from trivial, yet every control point is an affine combination of grid points.
  const glm::dvec3 origin(0.2, -0.1, 0.4);
  const glm::dvec3 e1 = glm::normalize(glm::dvec3(1.0, 0.2, 0.5));
  const glm::dvec3 e2 = glm::normalize(glm::cross(glm::dvec3(0.3, -0.4, 1.0), e1));
  const glm::dvec3 normal = glm::normalize(glm::cross(e1, e2));
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> jitter(-0.25, 0.25);
  const GridData grid = makeGrid(6, 5, [&](int i, int j) {
    const double a = -1.0 + 0.4 * i + jitter(rng), b = -0.8 + 0.4 * j + 0.3 * std::sin(3.0 * i);
    return origin + a * e1 + b * e2;
  });
  double worst = 0.0;
  for (const BezierPatch& p : interpolateGrid(grid))
    for (const glm::dvec3& q : p.cp) worst = std::max(worst, std::fabs(glm::dot(q - origin, normal)));
  INFO("largest distance of a control point from the plane: " << worst);
  CHECK(worst <= 1e-12);
}

TEST_CASE("interpolateGrid: bicubic polynomials on uniform spacing are reproduced exactly, "
          "border cells included",
          "[grid]") {
  // Not-a-knot splines reproduce cubics, so z = x² + y² (and any polynomial of degree ≤ 3 in
  // each of x and y) comes back to rounding everywhere; natural end conditions would bend
  // the border cells. Tolerance 1e-12 on values of order 1.
  const std::function<double(double, double)> surfaces[] = {
      [](double x, double y) { return x * x + y * y; },
      [](double x, double y) {
        return x * x * x * y - 0.5 * x * x * y * y * y + 0.3 * x * y - y * y * y;
      },
  };
  for (const auto& f : surfaces) {
    const int rows = 6, cols = 5;
    const double x0 = -1.0, y0 = -0.8, h = 0.4;
    const GridData grid = makeGrid(rows, cols, [&](int i, int j) {
      const double x = x0 + h * i, y = y0 + h * j;
      return glm::dvec3(x, y, f(x, y));
    });
    const std::vector<BezierPatch> patches = interpolateGrid(grid);
    double worst = 0.0;
    for (int i = 0; i + 1 < rows; ++i)
      for (int j = 0; j + 1 < cols; ++j)
        for (int a = 0; a <= 6; ++a)
          for (int b = 0; b <= 6; ++b) {
            const double u = a / 6.0, v = b / 6.0;
            const glm::dvec3 p = evaluate(patches[i * (cols - 1) + j], u, v);
            const double x = x0 + h * (i + u), y = y0 + h * (j + v);
            worst = std::max(
                {worst, std::fabs(p.x - x), std::fabs(p.y - y), std::fabs(p.z - f(x, y))});
          }
    INFO("largest deviation from the sampled polynomial: " << worst);
    CHECK(worst <= 1e-12);
  }
}

TEST_CASE("interpolateGrid: a 2×2 grid gives the bilinear patch", "[grid]") {
  const GridData grid{2, 2, {{0, 0, 0}, {0, 1, 0.5}, {1, 0, -0.25}, {1.5, 1.5, 1}}};
  const BezierPatch p = interpolateGrid(grid).at(0);
  for (double u : {0.0, 0.3, 0.7, 1.0})
    for (double v : {0.0, 0.4, 1.0}) {
      const glm::dvec3 bilinear = (1 - u) * (1 - v) * grid.points[0] + (1 - u) * v * grid.points[1] +
                                  u * (1 - v) * grid.points[2] + u * v * grid.points[3];
      CHECK(maxAbs(evaluate(p, u, v) - bilinear) <= 1e-14);
    }
}

TEST_CASE("interpolateGrid: neighbouring patches share their boundary control points bit for bit",
          "[grid]") {
  for (const auto& [name, grid] : testGrids()) {
    INFO(name);
    const std::vector<BezierPatch> patches = interpolateGrid(grid);
    const int cellCols = grid.cols - 1;
    int mismatches = 0, compared = 0;
    for (int i = 0; i + 1 < grid.rows; ++i)
      for (int j = 0; j + 1 < grid.cols; ++j) {
        const BezierPatch& p = patches[i * cellCols + j];
        for (int k = 0; k < 4; ++k) {
          if (i + 2 < grid.rows) {  // the cell after it along u: edge u = 1 against u = 0
            mismatches += !sameBits(p.at(3, k), patches[(i + 1) * cellCols + j].at(0, k));
            ++compared;
          }
          if (j + 2 < grid.cols) {  // along v: edge v = 1 against v = 0
            mismatches += !sameBits(p.at(k, 3), patches[i * cellCols + j + 1].at(k, 0));
            ++compared;
          }
        }
      }
    CHECK(compared == 4 * ((grid.rows - 2) * (grid.cols - 1) + (grid.rows - 1) * (grid.cols - 2)));
    CHECK(mismatches == 0);
  }
}

TEST_CASE("interpolateGrid: patches join C¹ (and C²) across cell boundaries", "[grid]") {
  // All cells have parameter length 1 (uniform parametrisation), so the per-patch derivatives
  // are compared unscaled.
  for (const auto& [name, grid] : testGrids()) {
    INFO(name);
    const std::vector<BezierPatch> patches = interpolateGrid(grid);
    const int cellCols = grid.cols - 1;
    double worstC1 = 0.0, worstC2 = 0.0, worstValue = 0.0;
    for (int i = 0; i + 1 < grid.rows; ++i)
      for (int j = 0; j + 1 < grid.cols; ++j) {
        const BezierPatch& p = patches[i * cellCols + j];
        for (double t : {0.0, 0.2, 0.5, 0.9, 1.0}) {
          if (i + 2 < grid.rows) {
            const BezierPatch& q = patches[(i + 1) * cellCols + j];
            worstValue = std::max(worstValue, maxAbs(evaluate(p, 1, t) - evaluate(q, 0, t)));
            worstC1 = std::max(worstC1, maxAbs(evaluate(p, 1, t, 1, 0) - evaluate(q, 0, t, 1, 0)));
            worstC1 = std::max(worstC1, maxAbs(evaluate(p, 1, t, 0, 1) - evaluate(q, 0, t, 0, 1)));
            worstC2 = std::max(worstC2, maxAbs(evaluate(p, 1, t, 2, 0) - evaluate(q, 0, t, 2, 0)));
          }
          if (j + 2 < grid.cols) {
            const BezierPatch& q = patches[i * cellCols + j + 1];
            worstValue = std::max(worstValue, maxAbs(evaluate(p, t, 1) - evaluate(q, t, 0)));
            worstC1 = std::max(worstC1, maxAbs(evaluate(p, t, 1, 0, 1) - evaluate(q, t, 0, 0, 1)));
            worstC1 = std::max(worstC1, maxAbs(evaluate(p, t, 1, 1, 0) - evaluate(q, t, 0, 1, 0)));
            worstC2 = std::max(worstC2, maxAbs(evaluate(p, t, 1, 0, 2) - evaluate(q, t, 0, 0, 2)));
          }
        }
      }
    INFO("largest jump: value " << worstValue << ", first derivative " << worstC1
                                << ", second derivative " << worstC2);
    CHECK(worstValue <= 1e-12);
    CHECK(worstC1 <= 1e-12);
    CHECK(worstC2 <= 1e-12);
  }
}

TEST_CASE("gridDerivatives: the two twist estimates (T^u along v, T^v along u) agree", "[grid]") {
  for (const auto& [name, grid] : testGrids()) {
    INFO(name);
    const GridDerivatives d = gridDerivatives(grid);
    REQUIRE(d.twist.size() == grid.points.size());
    double worst = 0.0, largest = 0.0;
    for (size_t k = 0; k < d.twist.size(); ++k) {
      worst = std::max(worst, maxAbs(d.twistFromTu[k] - d.twistFromTv[k]));
      largest = std::max(largest, maxAbs(d.twist[k]));
    }
    INFO("largest twist " << largest << ", largest disagreement " << worst);
    CHECK(largest > 1e-3);  // the comparison is not between zeros
    CHECK(worst <= 1e-12);
  }
}

TEST_CASE("the bundled .grid data sets load and interpolate", "[grid]") {
  const int expectedSize[] = {9, 11, 13};
  for (int s = 0; s < 3; ++s) {
    INFO(kDataSets[s]);
    const GridData grid = readGrid(kDataDir + kDataSets[s]);
    CHECK(grid.rows == expectedSize[s]);
    CHECK(grid.cols == expectedSize[s]);
    REQUIRE(grid.points.size() == static_cast<size_t>(grid.rows * grid.cols));
    for (const glm::dvec3& p : grid.points) CHECK(maxAbs(p) <= 1.0);
    // Rows along x, columns along y, as data/README.md says.
    CHECK(grid.at(grid.rows - 1, 0).x > grid.at(0, 0).x);
    CHECK(grid.at(0, grid.cols - 1).y > grid.at(0, 0).y);
    const std::vector<BezierPatch> patches = interpolateGrid(grid);
    CHECK(patches.size() == static_cast<size_t>((grid.rows - 1) * (grid.cols - 1)));
    for (const BezierPatch& p : patches) {
      const glm::dvec3 n = glm::cross(evaluate(p, 0.5, 0.5, 1, 0), evaluate(p, 0.5, 0.5, 0, 1));
      CHECK(n.z > 0.0);  // normals point up
    }
  }
}

TEST_CASE("interpolateGrid rejects grids it cannot interpolate", "[grid]") {
  auto grid = [](int rows, int cols) {
    return GridData{rows, cols, std::vector<glm::dvec3>(std::max(rows * cols, 0))};
  };
  CHECK_THROWS_WITH(interpolateGrid(grid(1, 5)), Contains("at least 2×2") && Contains("1×5"));
  CHECK_THROWS_WITH(interpolateGrid(grid(5, 1)), Contains("at least 2×2"));
  CHECK_THROWS_WITH(interpolateGrid(grid(0, 0)), Contains("at least 2×2"));
  GridData shortGrid = grid(3, 3);
  shortGrid.points.pop_back();
  CHECK_THROWS_WITH(interpolateGrid(shortGrid), Contains("needs 9 points, got 8"));
  GridData nanGrid = grid(3, 4);
  nanGrid.points[6].y = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(interpolateGrid(nanGrid), Contains("row 1, column 2") && Contains("not finite"));
  GridData infGrid = grid(3, 4);
  infGrid.points[11].z = std::numeric_limits<double>::infinity();
  CHECK_THROWS_WITH(interpolateGrid(infGrid), Contains("row 2, column 3"));
  GridData hugeGrid = grid(4, 4);
  hugeGrid.points[5].x = 1e308;
  hugeGrid.points[6].x = -1e308;
  CHECK_THROWS_WITH(interpolateGrid(hugeGrid), Contains("too large"));
  CHECK_THROWS_AS(interpolateGrid(grid(1, 5)), std::invalid_argument);
  CHECK_THROWS_AS(gridDerivatives(grid(2, 1)), std::invalid_argument);
}

namespace {

GridData parse(const std::string& text) {
  std::istringstream in(text);
  return parseGrid(in, "test.grid");
}

// The InputError parsing `text` throws; fails the test if there is none.
InputError parseError(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e;
  }
  FAIL("no InputError for:\n" << text);
  throw std::logic_error("unreachable");
}

// Checks kind, line and that the reason contains `needle`; what() must be file:line: reason.
void checkError(const std::string& text, InputErrorKind kind, int line, const std::string& needle) {
  const InputError e = parseError(text);
  INFO("text:\n" << text << "what(): " << e.what());
  CHECK(inputErrorKindName(e.kind()) == std::string(inputErrorKindName(kind)));
  CHECK(e.file() == "test.grid");
  CHECK(e.line() == line);
  CHECK_THAT(e.reason(), Contains(needle));
  CHECK(std::string(e.what()) == "test.grid:" + std::to_string(line) + ": " + e.reason());
}

}  // namespace

TEST_CASE("grid reader: comments, blank lines, CRLF and a leading '+' are accepted", "[grid]") {
  const GridData grid = parse(
      "# header comment\n\n  2 +3\r\n# between\n"
      "0 0 0\n0 1 0.5\r\n0 2 -1e-3\n\n1 0 +2\n  # indented comment\n1 1 1.25\n1 2 3\n\n# trailing\n");
  CHECK(grid.rows == 2);
  CHECK(grid.cols == 3);
  REQUIRE(grid.points.size() == 6);
  CHECK(grid.at(0, 2) == glm::dvec3(0, 2, -1e-3));
  CHECK(grid.at(1, 0) == glm::dvec3(1, 0, 2));
  CHECK(grid.at(1, 2) == glm::dvec3(1, 2, 3));
}

TEST_CASE("grid reader: malformed files name file, line and reason", "[grid]") {
  const std::string header = "# two by two\n2 2\n";  // size on line 2, points from line 3
  SECTION("empty or comment-only") {
    checkError("", InputErrorKind::Count, 1, "empty file");
    checkError("# nothing\n\n", InputErrorKind::Count, 3, "empty file");
  }
  SECTION("truncated") {
    checkError(header + "0 0 0\n0 1 0\n1 0 0\n", InputErrorKind::Count, 6,
               "file ends early: expected point 4 of 4 (row 1, column 1)");
    checkError(header, InputErrorKind::Count, 3, "expected point 1 of 4");
  }
  SECTION("wrong counts") {
    checkError(header + "0 0 0\n0 1 0\n1 0 0\n1 1 0\n2 0 0\n", InputErrorKind::Count, 7,
               "more points than the 2×2 = 4 points declared on line 2");
    checkError(header + "0 0 0\n0 1 0\n1 0 0\n1 1 0\nend\n", InputErrorKind::Syntax, 7,
               "unexpected content 'end'");
    checkError("1 4\n", InputErrorKind::Count, 1, "rows must be at least 2, found 1");
    checkError("3 0\n", InputErrorKind::Count, 1, "cols must be at least 2, found 0");
    checkError("3 -2\n", InputErrorKind::Count, 1, "cols must be at least 2");
    checkError("100000 100000\n", InputErrorKind::Range, 1, "more than");
    checkError("99999999999999999999 2\n", InputErrorKind::Range, 1, "too large");
    checkError("2 2 2\n", InputErrorKind::Syntax, 1, "found 3 tokens");
    checkError("4\n", InputErrorKind::Syntax, 1, "\"rows cols\"");
    checkError(header + "0 0 0\n0 1\n", InputErrorKind::Syntax, 4,
               "expected 3 numbers \"x y z\" for point 2 of 4 (row 0, column 1), found 2 tokens");
    checkError(header + "0 0 0 # origin\n", InputErrorKind::Syntax, 3,
               "'#' starts a comment only at the beginning of a line");
  }
  SECTION("non-finite and out of range") {
    checkError(header + "0 0 0\n0 nan 0\n", InputErrorKind::NonFinite, 4,
               "'nan' is not a finite number (y of point 2 of 4 (row 0, column 1))");
    checkError(header + "0 0 0\n0 1 0\n1 0 -inf\n", InputErrorKind::NonFinite, 5, "'-inf'");
    checkError(header + "1e400 0 0\n", InputErrorKind::Range, 3, "outside the range of a double");
    checkError(header + "0 0 2e15\n", InputErrorKind::Range, 3, "largest accepted magnitude");
  }
  SECTION("not numbers") {
    checkError(header + "0 0 0\n1.0 abc 2\n", InputErrorKind::Syntax, 4,
               "'abc' is not a number (y of point 2");
    checkError(header + "1,5 0 0\n", InputErrorKind::Syntax, 3,
               "'1,5' is not a number (x of point 1");
    checkError(header + "0 0 0x1p3\n", InputErrorKind::Syntax, 3, "'0x1p3' is not a number");
    checkError(header + "0 0 +-1\n", InputErrorKind::Syntax, 3, "'+-1' is not a number");
    checkError("2.5 3\n", InputErrorKind::Syntax, 1, "'2.5' is not an integer (rows)");
    checkError("2 three\n", InputErrorKind::Syntax, 1, "'three' is not an integer (cols)");
  }
}

TEST_CASE("grid reader: files on disk", "[grid]") {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("tessera_test_grid_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string bad = (dir / "bad.grid").string();
  {
    std::ofstream out(bad);
    out << "2 2\n0 0 0\n0 1 0\n1 0 nan\n1 1 0\n";
  }
  try {
    readGrid(bad);
    FAIL("no error for " << bad);
  } catch (const InputError& e) {
    CHECK(e.kind() == InputErrorKind::NonFinite);
    CHECK(e.file() == bad);
    CHECK(e.line() == 4);
    CHECK_THAT(std::string(e.what()), Contains(bad + ":4: 'nan' is not a finite number"));
  }
  const std::string missing = (dir / "missing.grid").string();
  try {
    readGrid(missing);
    FAIL("no error for " << missing);
  } catch (const InputError& e) {
    CHECK(e.kind() == InputErrorKind::Io);
    CHECK(e.file() == missing);
    CHECK(e.line() == 0);
    CHECK_THAT(std::string(e.what()), Contains("cannot open for reading"));
  }
  try {
    readGrid(dir.string());
    FAIL("no error for the directory " << dir);
  } catch (const InputError& e) {
    CHECK(e.kind() == InputErrorKind::Io);
    CHECK_THAT(std::string(e.what()), Contains("is a directory"));
  }
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
}
