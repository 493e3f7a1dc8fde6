// The directional cell bound (host/division/detail/directional.h): the simplex maximum against a brute
// force scan, the cell bound never below the densely measured deviation of the cell's two
// triangles (random rational cells with zero and negative weights), exact where S'' is
// constant, and the same bound whether the numerators come from the patch or the cell's net.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "division/deviation.h"
#include "division/detail/directional.h"
#include "division_samples.h"
#include "geometry/homogeneous_net.h"

using namespace tessera;
using namespace tessera::test;

namespace {

double bruteSimplexMax(double c01, double c12, double c02, int steps) {
  double best = 0.0;
  for (int a = 0; a <= steps; ++a)
    for (int b = 0; a + b <= steps; ++b) {
      const double l0 = double(a) / steps, l1 = double(b) / steps, l2 = 1.0 - l0 - l1;
      best = std::max(best, c01 * l0 * l1 + c12 * l1 * l2 + c02 * l0 * l2);
    }
  return best;
}

// The numerators of S'' and w³ of `net` restricted to [u0,u1]×[v0,v1] (values stay derivatives
// in the net's parameters), as the division search restricts them.
SecondDerivativeNumerators restricted(const HomogeneousNet& net, double u0, double u1,
                                      double v0, double v1) {
  return restrictNumerators(secondDerivativeNumerators(net), u0, u1, v0, v1);
}

// S(u, v) = (u, v, a u² + b uv + c v²) as a biquadratic net: S'' is constant.
HomogeneousNet quadraticSurface(double a, double b, double c) {
  HomogeneousNet net(2, 2);
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j)
      net.at(i, j) = glm::dvec4(0.5 * i, 0.5 * j,
                                a * (i == 2) + b * (0.5 * i) * (0.5 * j) + c * (j == 2), 1.0);
  return net;
}

}  // namespace

TEST_CASE("Directional bound: the simplex maximum matches a brute-force scan", "[division]") {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> coefficient(0.0, 1.0);
  double worstExcess = 0.0;
  for (int trial = 0; trial < 300; ++trial) {
    double c[3] = {coefficient(rng), coefficient(rng), coefficient(rng)};
    if (trial % 5 == 0) c[trial % 3] = 0.0;               // a zero edge
    if (trial % 7 == 0) c[trial % 3] = 3.0;               // one edge dominates
    if (trial % 11 == 0) c[0] = c[1] = c[2];              // equal edges: c/3 at the centroid
    const double exact = largestSimplexProduct(c[0], c[1], c[2]);
    const double scanned = bruteSimplexMax(c[0], c[1], c[2], 600);
    INFO("c = " << c[0] << ", " << c[1] << ", " << c[2]);
    CHECK(exact >= scanned);
    CHECK(exact <= scanned * (1 + 1e-4) + 1e-15);
    worstExcess = std::max(worstExcess, exact / std::max(scanned, 1e-300) - 1.0);
  }
  CHECK(largestSimplexProduct(1, 1, 1) == Approx(1.0 / 3.0));
  WARN("largest excess of the closed form over a 600-step scan: " << worstExcess);
}

TEST_CASE("Directional bound: exact where S'' is constant, well below Filip's there",
          "[division]") {
  // a u² − 1.5 uv + v²: S_uu = 2, S_uv = −1.5, S_vv = 2 along z; along the diagonal the second
  // derivative is 2 − 3 + 2 = 1, so the worst point is inside the triangle, not on an edge.
  const HomogeneousNet net = quadraticSurface(1.0, -1.5, 1.0);
  const double bound = directionalCellBound(restricted(net, 0, 1, 0, 1), 1.0, 1.0, 0, 0.0);
  const double measured = uniformGridDeviation(net, 1, 1, {240, 240});
  const double filip = (2.0 + 2 * 1.5 + 2.0) / 8.0;
  CHECK(bound == Approx(2.0 / 7.0).epsilon(1e-9));  // ½ · 4/7
  CHECK(bound >= measured);
  CHECK(measured >= 0.999 * bound);
  CHECK(bound < 0.35 * filip);
  WARN("constant S'': directional bound " << bound << ", measured " << measured << ", Filip "
                                          << filip);
}

TEST_CASE("Directional bound: never below the measured deviation of random rational cells",
          "[division]") {
  std::mt19937 rng(808);
  int tested = 0, unresolved = 0, zeros = 0, negatives = 0;
  double tightest = 0.0, sumRatio = 0.0, worstScaleMismatch = 0.0;
  for (int trial = 0; tested < 1000 && trial < 4000; ++trial) {
    const RandomCell sample = randomCell(trial, rng);
    const HomogeneousNet& net = sample.patch;
    const HomogeneousNet& cell = sample.cell;
    const double u0 = sample.u0, v0 = sample.v0, h = sample.h, k = sample.k;
    const int refinement = trial % 3;
    const double bound =
        directionalCellBound(restricted(net, u0, u0 + h, v0, v0 + k), h, k, refinement, 0.0);
    if (!std::isfinite(bound)) {
      ++unresolved;  // w³ changes sign on the cell: the method falls back to Filip there
      continue;
    }
    // The same cell from its own net: derivatives in its own parameters, h = k = 1.
    const double own =
        directionalCellBound(restricted(cell, 0, 1, 0, 1), 1.0, 1.0, refinement, 0.0);
    worstScaleMismatch = std::max(worstScaleMismatch, std::abs(own - bound) / bound);
    const double measured = uniformGridDeviation(cell, 1, 1, {48, 48});
    INFO("trial " << trial << ": bound " << bound << ", measured " << measured);
    CHECK(measured <= bound * (1 + 1e-9));
    tightest = std::max(tightest, measured / bound);
    sumRatio += measured / bound;
    ++tested;
    zeros += hasZeroWeight(net);
    negatives += hasNegativeWeight(net);
  }
  WARN(tested << " cells (" << zeros << " of patches with zero weights, " << negatives
              << " with negative ones), " << unresolved
              << " with w³ changing sign; measured/bound: largest " << tightest << ", mean "
              << sumRatio / std::max(1, tested) << "; patch vs own net relative difference "
              << worstScaleMismatch);
  CHECK(tested == 1000);
  CHECK(zeros >= 200);
  CHECK(negatives >= 200);
  CHECK(worstScaleMismatch < 1e-8);
}
