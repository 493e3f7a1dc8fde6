// The direct deviation bound (host/division/detail/direct.h): never below the densely measured
// deviation of a cell's two triangles (random rational cells with zero and negative weights),
// tending to it as the squares shrink, and the adaptive pass/fail test agreeing with both: it
// never passes a cell that measures above the tolerance, and always passes one whose uniform
// bound is within it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "division/deviation.h"
#include "division/detail/direct.h"
#include "division_samples.h"
#include "geometry/homogeneous_net.h"

using namespace tessera;
using namespace tessera::test;

TEST_CASE("Direct bound: never below the measured deviation of random rational cells, and tight",
          "[division]") {
  std::mt19937 rng(2718);
  constexpr int kDepths = 5;  // uniform squares 1, 2×2, ..., 16×16
  int tested = 0, unresolved = 0, zeros = 0, negatives = 0;
  double sumRatio[kDepths] = {}, worstRatio[kDepths] = {};
  for (int trial = 0; tested < 1000 && trial < 4000; ++trial) {
    const RandomCell sample = randomCell(trial, rng);
    const HomogeneousNet& cell = sample.cell;
    const double finest = cellDeviationBound(cell, kDepths - 1);
    if (!std::isfinite(finest)) {
      ++unresolved;  // w changes sign on the cell, or vanishes at a corner
      continue;
    }
    const double measured = uniformGridDeviation(cell, 1, 1, {48, 48});
    INFO("trial " << trial << ": measured " << measured);
    double previous = INFINITY;
    for (int d = 0; d < kDepths; ++d) {
      const double bound = cellDeviationBound(cell, d);
      INFO("depth " << d << ": bound " << bound);
      CHECK(measured <= bound * (1 + 1e-9));
      CHECK(bound <= previous * (1 + 1e-9));  // a sub-square's hull lies in its parent's
      previous = bound;
      if (std::isfinite(bound)) {
        sumRatio[d] += measured / bound;
        worstRatio[d] = std::max(worstRatio[d], measured / bound);
      }
    }
    // The adaptive test: never proves a tolerance the measurement breaks, always proves one
    // the uniform 16×16 bound meets.
    if (measured > 0) CHECK_FALSE(cellDeviationWithin(cell, 0.98 * measured, 8));
    CHECK(cellDeviationWithin(cell, finest * (1 + 1e-9), kDepths - 1));
    ++tested;
    zeros += hasZeroWeight(sample.patch);
    negatives += hasNegativeWeight(sample.patch);
  }
  WARN(tested << " cells (" << zeros << " of patches with zero weights, " << negatives
              << " with negative ones), " << unresolved << " unresolved; mean measured/bound at "
              << "1, 2², 4², 8², 16² squares: " << sumRatio[0] / tested << ", "
              << sumRatio[1] / tested << ", " << sumRatio[2] / tested << ", "
              << sumRatio[3] / tested << ", " << sumRatio[4] / tested);
  CHECK(tested == 1000);
  CHECK(zeros >= 200);
  CHECK(negatives >= 200);
  CHECK(sumRatio[kDepths - 1] / tested > 0.9);  // the bound tends to the sup
}

TEST_CASE("Direct bound: a planar bilinear cell has no deviation, a cylinder cell its sagitta",
          "[division]") {
  // The triangles of a planar cell with a linear parametrisation lie on it exactly.
  HomogeneousNet plane(1, 1);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) plane.at(i, j) = glm::dvec4(i, j, 0.5 * i + 0.25 * j, 1.0);
  CHECK(cellDeviationBound(plane, 0) <= 1e-15);
  CHECK(cellDeviationWithin(plane, 1e-12, 0));
  // A quarter circle (rational quadratic, weight √½) extruded along z: the largest deviation
  // of the chord triangles is the arc's sagitta 1 − cos 45° = 0.293 (the parametrisation is
  // symmetric, so the arc's middle sits at the chord's middle parameter); the bound must meet
  // the dense measurement from above and come within 1 % of it at 16×16 squares.
  HomogeneousNet cylinder(2, 1);
  const double s = std::sqrt(0.5);
  const glm::dvec4 arc[3] = {{1, 0, 0, 1}, {s, s, 0, s}, {0, 1, 0, 1}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) cylinder.at(i, j) = arc[i] + glm::dvec4(0, 0, j * arc[i].w, 0);
  const double measured = uniformGridDeviation(cylinder, 1, 1, {200, 200});
  const double bound = cellDeviationBound(cylinder, 4);
  CHECK(bound >= measured);
  CHECK(bound <= 1.01 * measured);
  CHECK(measured == Approx(1.0 - s).epsilon(1e-6));
}
