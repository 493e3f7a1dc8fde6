// The real-time counts from a screen-space net (host/division/projected.h), on teapot and random
// bicubic patches seen by random cameras, weak to strong perspective: the projected-grid bound
// is never below the deviation measured on the grids it sizes (nor on fixed grids) and is
// Filip's polynomial bound of the projected points when all weights are equal; the estimate's
// grids stay within the tolerance where measured here (its margin: docs/realtime.md) with about
// half the bound's faces; both refuse a net that reaches the eye plane.
#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <random>

#include "division/deviation.h"
#include "division/projected.h"
#include "division/view_dependent.h"
#include "geometry/homogeneous_net.h"
#include "geometry/rational.h"
#include "io/bpt_reader.h"
#include "patch_samples.h"

using namespace tessera;

namespace {

struct ScreenCase {
  RationalBezierPatch screen;
  double weightRatio = 1;  // largest / smallest weight: how strong the perspective is
};

// Teapot patches and random ones seen from random eyes 2..40 units away, 640×480, kept when
// every weight is > 0 and the patch's image is at most 2,000 px across.
std::vector<ScreenCase> screenCases(size_t wanted, uint32_t seed) {
  std::vector<BezierPatch> patches = readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt");
  for (const BezierPatch& p : test::randomBicubicPatches(32, seed)) patches.push_back(p);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), distance(2.0, 40.0);
  std::vector<ScreenCase> cases;
  while (cases.size() < wanted) {
    const BezierPatch& patch = patches[rng() % patches.size()];
    glm::dvec3 centre(0.0);
    for (const glm::dvec3& c : patch.cp) centre += c / 16.0;
    const glm::dvec3 direction = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
    const Camera camera = lookAtCamera(centre + distance(rng) * direction, centre, {0, 0, 1},
                                       0.8, 640, 480, 0.05, 500.0);
    ScreenCase c{screenSpacePatch(toRationalPatch(patch), camera)};
    double wMin = INFINITY, wMax = 0;
    glm::dvec2 lo(INFINITY), hi(-INFINITY);
    for (const glm::dvec4& h : c.screen.cpw) {
      wMin = std::min(wMin, h.w);
      wMax = std::max(wMax, h.w);
      lo = glm::min(lo, glm::dvec2(h) / h.w);
      hi = glm::max(hi, glm::dvec2(h) / h.w);
    }
    if (!(wMin > 0.05) || glm::length(hi - lo) > 2000.0) continue;
    c.weightRatio = wMax / wMin;
    cases.push_back(c);
  }
  return cases;
}

double boundAt(const SecondDerivativeBounds& b, int nu, int nv) {
  const double h = 1.0 / nu, k = 1.0 / nv;
  return (h * h * b.uu + 2.0 * h * k * b.uv + k * k * b.vv) / 8.0;
}

}  // namespace

TEST_CASE("projected-grid bound: never below the measured deviation", "[division][projected]") {
  const std::vector<ScreenCase> cases = screenCases(300, 16);
  double largestRatio = 0, largestWeightRatio = 1;
  size_t grids = 0;
  for (const ScreenCase& c : cases) {
    const SecondDerivativeBounds b = projectedGridBounds(c.screen.cpw.data(), 3, 3);
    REQUIRE(b.bounded);
    const Divisions d = divisionsFromBounds(b, 1.0, 64);
    const HomogeneousNet net = toNet(c.screen);
    for (const auto& [nu, nv] : {std::pair<int, int>{d.nu, d.nv}, {1, 1}, {2, 3}, {5, 4}}) {
      const double bound = boundAt(b, nu, nv), measured = uniformGridDeviation(net, nu, nv);
      CHECK(measured <= bound);
      largestRatio = std::max(largestRatio, measured / bound);
      ++grids;
    }
    if (d.status == DivisionStatus::Ok) CHECK(uniformGridDeviation(net, d.nu, d.nv) <= 1.0);
    largestWeightRatio = std::max(largestWeightRatio, c.weightRatio);
  }
  WARN(grids << " grids of " << cases.size() << " screen-space patches (weights up to "
             << largestWeightRatio << "x apart): measured/bound at most " << largestRatio);
  CHECK(largestWeightRatio > 2.0);  // the set does exercise strong perspective
}

TEST_CASE("projected-grid bound: Filip's polynomial bound when the weights are equal",
          "[division][projected]") {
  // A plane patch seen straight on: every weight 2.5, the projection affine.
  const BezierPatch patch = test::randomBicubicPatches(1, 7)[0];
  std::vector<glm::dvec4> net;
  for (const glm::dvec3& c : patch.cp) net.push_back(glm::dvec4(2.5 * c.x, 2.5 * c.y, 0.0, 2.5));
  const SecondDerivativeBounds b = projectedGridBounds(net.data(), 3, 3);
  double d2u = 0, d2v = 0, duv = 0;
  auto p = [&](int i, int j) { return glm::dvec2(patch.at(i, j)); };
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      if (i < 2) d2u = std::max(d2u, glm::length(p(i + 2, j) - 2.0 * p(i + 1, j) + p(i, j)));
      if (j < 2) d2v = std::max(d2v, glm::length(p(i, j + 2) - 2.0 * p(i, j + 1) + p(i, j)));
      if (i < 3 && j < 3)
        duv = std::max(duv, glm::length(p(i + 1, j + 1) - p(i + 1, j) - p(i, j + 1) + p(i, j)));
    }
  CHECK(b.uu == Approx(6.0 * d2u).epsilon(1e-9));
  CHECK(b.uv == Approx(9.0 * duv).epsilon(1e-9));
  CHECK(b.vv == Approx(6.0 * d2v).epsilon(1e-9));
}

TEST_CASE("projected counts: a net that reaches the eye plane is refused", "[division][projected]") {
  std::vector<glm::dvec4> net(16, glm::dvec4(10.0, 20.0, 0.0, 1.0));
  net[5].w = 0.0;
  CHECK_FALSE(projectedGridBounds(net.data(), 3, 3).bounded);
  CHECK(estimatedProjectedDivisions(net.data(), 3, 3, 1.0, 64).status == DivisionStatus::Unbounded);
  net[5].w = -0.5;
  CHECK_FALSE(projectedGridBounds(net.data(), 3, 3).bounded);
  CHECK_THROWS_AS(projectedGridBounds(net.data(), 4, 3), std::invalid_argument);
}

TEST_CASE("projected estimate: within the tolerance where measured, about half the faces",
          "[division][projected]") {
  const std::vector<ScreenCase> cases = screenCases(300, 61);
  long long estimatedFaces = 0, boundFaces = 0;
  double largest = 0;
  for (const ScreenCase& c : cases) {
    const Divisions e = estimatedProjectedDivisions(c.screen.cpw.data(), 3, 3, 1.0, 64);
    const Divisions b =
        divisionsFromBounds(projectedGridBounds(c.screen.cpw.data(), 3, 3), 1.0, 64);
    if (e.status != DivisionStatus::Ok || b.status != DivisionStatus::Ok) continue;
    estimatedFaces += e.divisionNumber();
    boundFaces += b.divisionNumber();
    const double measured = uniformGridDeviation(toNet(c.screen), e.nu, e.nv);
    largest = std::max(largest, measured);
    CHECK(measured <= 1.0);
  }
  WARN("estimate: " << estimatedFaces << " faces, bound: " << boundFaces
                    << "; largest measured deviation at the estimate's counts " << largest);
  CHECK(estimatedFaces < 0.7 * boundFaces);
}

TEST_CASE("projected estimate: curves, and strips joining fewer edge segments",
          "[division][projected]") {
  // A planar cubic curve seen straight on: its count is Filip's, ceil(sqrt(6·max|Δ²p|/8)).
  const std::vector<glm::dvec4> curve = {{0, 0, 0, 1}, {40, 90, 0, 1}, {80, -60, 0, 1}, {120, 0, 0, 1}};
  const double d2 = std::max(glm::length(glm::dvec2(80, -60) - 2.0 * glm::dvec2(40, 90)),
                             glm::length(glm::dvec2(120, 0) - 2.0 * glm::dvec2(80, -60) +
                                         glm::dvec2(40, 90)));
  const Divisions d = estimatedProjectedDivisions(curve.data(), 3, 0, 1.0, 64);
  CHECK(d.nu == int(std::ceil(std::sqrt(6.0 * d2 / 8.0))));
  CHECK(d.nv == 1);
  // Edges of one segment each: the strips' triangles span whole sides, so the counts across
  // them grow; edge counts as large as the patch's change nothing.
  for (const ScreenCase& c : screenCases(40, 5)) {
    const Divisions alone = estimatedProjectedDivisions(c.screen.cpw.data(), 3, 3, 1.0, 64);
    if (alone.status != DivisionStatus::Ok || alone.nu < 3 || alone.nv < 3) continue;
    const std::array<int, 4> coarse{1, 1, 1, 1}, fine{64, 64, 64, 64};
    const Divisions withCoarse =
        estimatedProjectedDivisions(c.screen.cpw.data(), 3, 3, 1.0, 64, &coarse);
    const Divisions withFine = estimatedProjectedDivisions(c.screen.cpw.data(), 3, 3, 1.0, 64, &fine);
    CHECK(withFine.nu == alone.nu);
    CHECK(withFine.nv == alone.nv);
    CHECK(withCoarse.nu >= alone.nu);
    CHECK(withCoarse.nv >= alone.nv);
    CHECK(withCoarse.nu * withCoarse.nv > alone.nu * alone.nv);
  }
}
