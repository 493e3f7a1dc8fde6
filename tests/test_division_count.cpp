// Division counts for rational Bézier curves and patches (host/division/count.h): worked
// cases, the corrected A_ijk, the methods against each other, the closed-form counts.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <stdexcept>

#include "geometry/bernstein.h"
#include "division/count.h"
#include "division/deviation.h"
#include "geometry/homogeneous_net.h"
#include "experiments/rational_samples.h"

using namespace tessera;

namespace {

glm::dvec4 homogeneous(const glm::dvec3& p, double w) { return glm::dvec4(w * p, w); }

RationalBezierCurve randomCurve(int degree, std::mt19937& rng) {
  std::uniform_real_distribution<double> coord(-1.0, 1.0), weight(0.2, 2.0);
  RationalBezierCurve c;
  c.degree = degree;
  for (int k = 0; k <= degree; ++k)
    c.cpw.push_back(homogeneous({coord(rng), coord(rng), coord(rng)}, weight(rng)));
  return c;
}

// Σ A_ijk B_i B_j B_k at t: w³·c''(t) if A_ijk is right.
glm::dvec3 tripleSum(const RationalBezierCurve& c, double t, bool asPrinted) {
  double b[kMaxDegree + 1];
  bernsteinBasis(c.degree, t, b);
  glm::dvec3 sum(0.0);
  for (int i = 0; i <= c.degree; ++i)
    for (int j = 0; j <= c.degree; ++j)
      for (int k = 0; k <= c.degree; ++k)
        sum += b[i] * b[j] * b[k] *
               (asPrinted ? abiEzziCoefficientAsPrinted(c, i, j, k) : abiEzziCoefficient(c, i, j, k));
  return sum;
}

DivisionOptions withMethod(DivisionMethod method, double tolerance) {
  DivisionOptions o;
  o.method = method;
  o.tolerance = tolerance;
  return o;
}

}  // namespace

TEST_CASE("Division: the corrected A_ijk sums to w³·c'', the printed one does not",
          "[division]") {
  std::mt19937 rng(5);
  double worstCorrected = 0.0, worstPrinted = 0.0;
  for (int degree = 1; degree <= kMaxDegree; ++degree)
    for (int trial = 0; trial < 5; ++trial) {
      const RationalBezierCurve c = randomCurve(degree, rng);
      const HomogeneousNet net = toNet(c);
      for (double t : {0.0, 0.17, 0.5, 0.83, 1.0}) {
        const ProjectedSecondDerivatives d = projectedDerivatives(net, t, 0.0);
        const glm::dvec3 exact = d.puu * d.w * d.w * d.w;
        const double scale = 1.0 + glm::length(exact);
        worstCorrected =
            std::max(worstCorrected, glm::length(tripleSum(c, t, false) - exact) / scale);
        if (degree >= 3)
          worstPrinted = std::max(worstPrinted, glm::length(tripleSum(c, t, true) - exact) / scale);
      }
    }
  INFO("corrected: worst relative error " << worstCorrected << "; as printed: " << worstPrinted);
  CHECK(worstCorrected < 1e-12);
  CHECK(worstPrinted > 1e-2);  // the slips of (3.2) change the value, not only the rounding
}

TEST_CASE("Division: parabola, Filip's bound is exact (count 10 at TOL 0.01)", "[division]") {
  // c'' = 2(P0 − 2P1 + P2) = (0, −8): the chord of a segment of length h deviates h²·8/8.
  const RationalBezierCurve parabola{
      2, {homogeneous({0, 0, 0}, 1), homogeneous({1, 2, 0}, 1), homogeneous({2, 0, 0}, 1)}};
  for (DivisionMethod method :
       {DivisionMethod::AbiEzzi, DivisionMethod::Split, DivisionMethod::Subdivided}) {
    INFO(divisionMethodName(method));
    const Divisions d = curveDivisions(parabola, withMethod(method, 0.0101));
    CHECK(d.bounds.uu == Approx(8.0).epsilon(1e-12));
    CHECK(d.realU == Approx(std::sqrt(8.0 / (8.0 * 0.0101))).epsilon(1e-12));
    CHECK(d.nu == 10);
    CHECK(d.nv == 1);
  }
  const HomogeneousNet net = toNet(parabola);
  CHECK(uniformGridDeviation(net, 10, 1) <= 0.0101);
  CHECK(uniformGridDeviation(net, 9, 1) > 0.0101);  // one fewer is too few: the bound is tight
}

TEST_CASE("Division: semicircle with a zero middle weight, every method that accepts it",
          "[division]") {
  // Weights (1, 0, 1): the middle control point is a direction; the curve is the unit
  // semicircle, c(t) = ((1−2t), 2t(1−t)) / (1 − 2t + 2t²).
  const RationalBezierCurve semi{
      2, {homogeneous({1, 0, 0}, 1), glm::dvec4(0, 1, 0, 0), homogeneous({-1, 0, 0}, 1)}};
  for (double t : {0.1, 0.5, 0.9}) {
    const ProjectedSecondDerivatives d = projectedDerivatives(toNet(semi), t, 0.0);
    CHECK(glm::length(d.p) == Approx(1.0).epsilon(1e-14));
  }
  CHECK_THROWS_AS(curveDivisions(semi, withMethod(DivisionMethod::AbiEzzi, 0.01)),
                  std::invalid_argument);
  const SampledSecondDerivatives sampled = sampledSecondDerivatives(toNet(semi), 2000);
  for (DivisionMethod method :
       {DivisionMethod::PaperSplit, DivisionMethod::Split, DivisionMethod::Subdivided}) {
    INFO(divisionMethodName(method));
    const Divisions d = curveDivisions(semi, withMethod(method, 0.001));
    INFO("bound " << d.bounds.uu << ", sampled max " << sampled.uu << ", count " << d.nu);
    CHECK(d.status == DivisionStatus::Ok);
    CHECK(d.bounds.uu >= sampled.uu);
    CHECK(uniformGridDeviation(toNet(semi), d.nu, 1) <= 0.001);
  }
}

TEST_CASE("Division: the paper's B1..B8 under-estimates when zero weights carry > half the mass",
          "[division]") {
  // Degree 5 with every interior weight zero: β = 1 − (1−t)⁵ − t⁵ reaches 15/16 at t = ½
  // where w is small, so β/w is far above the paper's 1/min w. (Found by a random search.)
  const RationalBezierCurve c{5,
                              {glm::dvec4(-0.572, -0.483, 0, 1.654), glm::dvec4(0.729, 0.141, 0, 0),
                               glm::dvec4(0.680, 0.287, 0, 0), glm::dvec4(0.704, 0.120, 0, 0),
                               glm::dvec4(0.577, 0.032, 0, 0), glm::dvec4(-0.607, -0.424, 0, 1.475)}};
  const SampledSecondDerivatives sampled = sampledSecondDerivatives(toNet(c), 4000);
  const Divisions paper = curveDivisions(c, withMethod(DivisionMethod::PaperSplit, 0.01));
  const Divisions split = curveDivisions(c, withMethod(DivisionMethod::Split, 0.01));
  INFO("sampled max ‖c''‖ " << sampled.uu << ", paper " << paper.bounds.uu << ", split "
                            << split.bounds.uu);
  CHECK(paper.bounds.uu < 0.5 * sampled.uu);  // not a bound
  CHECK(uniformGridDeviation(toNet(c), paper.nu, 1) > 0.01);  // and it under-divides
  CHECK(split.bounds.uu >= sampled.uu);
  CHECK(uniformGridDeviation(toNet(c), split.nu, 1) <= 0.01);
}

TEST_CASE("Division: Abi-Ezzi, split and a brute-force max over A_ijk agree for positive weights",
          "[division]") {
  std::mt19937 rng(17);
  for (int degree = 1; degree <= kMaxDegree; ++degree)
    for (int trial = 0; trial < 4; ++trial) {
      RationalBezierCurve c = randomCurve(degree, rng);
      if (trial == 3)
        for (glm::dvec4& h : c.cpw) h = -h;  // all negative: the same curve, the same bound
      double brute = 0.0;
      for (int i = 0; i <= degree; ++i)
        for (int j = 0; j <= degree; ++j)
          for (int k = 0; k <= degree; ++k)
            brute = std::max(brute, glm::length(abiEzziCoefficient(c, i, j, k)) /
                                        std::abs(c.cpw[i].w * c.cpw[j].w * c.cpw[k].w));
      const Divisions abi = curveDivisions(c, withMethod(DivisionMethod::AbiEzzi, 0.01));
      const Divisions split = curveDivisions(c, withMethod(DivisionMethod::Split, 0.01));
      INFO("degree " << degree << " trial " << trial);
      CHECK(abi.bounds.uu == Approx(brute).epsilon(1e-12));
      CHECK(split.bounds.uu == abi.bounds.uu);
      CHECK(split.nu == abi.nu);
    }
  std::mt19937 rngPatch(18);
  std::uniform_real_distribution<double> coord(-1.0, 1.0), weight(0.3, 2.0);
  for (int trial = 0; trial < 20; ++trial) {
    RationalBezierPatch p;
    p.degreeU = 1 + trial % 4;
    p.degreeV = 1 + (trial / 4) % 3;
    for (int k = 0; k < (p.degreeU + 1) * (p.degreeV + 1); ++k)
      p.cpw.push_back(homogeneous({coord(rng), coord(rng), coord(rng)}, weight(rngPatch)));
    const Divisions abi = patchDivisions(p, withMethod(DivisionMethod::AbiEzzi, 0.01));
    const Divisions split = patchDivisions(p, withMethod(DivisionMethod::Split, 0.01));
    CHECK(split.bounds.uu == abi.bounds.uu);
    CHECK(split.bounds.uv == abi.bounds.uv);
    CHECK(split.bounds.vv == abi.bounds.vv);
    CHECK(split.divisionNumber() == abi.divisionNumber());
  }
}

TEST_CASE("Division: a quarter cylinder needs divisions along the arc only", "[division]") {
  const RationalBezierPatch cyl = quarterCylinder(1.0, 3.0);
  for (DivisionMethod method : {DivisionMethod::AbiEzzi, DivisionMethod::Split}) {
    INFO(divisionMethodName(method));
    const Divisions d = patchDivisions(cyl, withMethod(method, 0.001));
    INFO("N_u " << d.nu << ", N_v " << d.nv << ", bounds " << d.bounds.uu << " " << d.bounds.uv
                << " " << d.bounds.vv);
    CHECK(d.bounds.vv == Approx(0.0).margin(1e-12));  // straight along the axis
    CHECK(d.bounds.uv == Approx(0.0).margin(1e-12));  // the arc does not change with height
    CHECK(d.nv == 1);
    CHECK(d.nu > 10);
    CHECK(d.divisionNumber() == static_cast<long long>(d.nu) * d.nv);
    CHECK(uniformGridDeviation(toNet(cyl), d.nu, d.nv) <= 0.001);
  }
  // Swapping u and v swaps the counts.
  RationalBezierPatch swapped;
  swapped.degreeU = cyl.degreeV;
  swapped.degreeV = cyl.degreeU;
  for (int j = 0; j <= cyl.degreeV; ++j)
    for (int i = 0; i <= cyl.degreeU; ++i) swapped.cpw.push_back(cyl.at(i, j));
  const Divisions a = patchDivisions(cyl, withMethod(DivisionMethod::Split, 0.001));
  const Divisions b = patchDivisions(swapped, withMethod(DivisionMethod::Split, 0.001));
  CHECK(a.nu == b.nv);
  CHECK(a.nv == b.nu);
}

TEST_CASE("Division: closed-form counts meet Filip's inequality with the smallest real product",
          "[division]") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> mag(0.0, 1.0);
  for (int trial = 0; trial < 500; ++trial) {
    SecondDerivativeBounds b;
    b.uu = trial % 5 == 0 ? 0.0 : std::pow(10.0, 4 * mag(rng) - 1);
    b.uv = trial % 3 == 0 ? 0.0 : std::pow(10.0, 4 * mag(rng) - 1);
    b.vv = trial % 7 == 0 ? 0.0 : std::pow(10.0, 4 * mag(rng) - 1);
    const double tol = 0.01, T = 8 * tol;
    const Divisions d = divisionsFromBounds(b, tol, 1 << 20);
    INFO("a " << b.uu << " b " << b.uv << " c " << b.vv << " → " << d.realU << " × " << d.realV);
    const double lhs = b.uu / (d.nu * double(d.nu)) + 2 * b.uv / (d.nu * double(d.nv)) +
                       b.vv / (d.nv * double(d.nv));
    CHECK(lhs <= T * (1 + 1e-12));
    // No real N_u ≥ 1 (N_v solved from the inequality, ≥ 1) gives a smaller product.
    double best = INFINITY;
    for (double nu = 1.0; nu < 4 * d.realU + 4; nu *= 1.0005) {
      const double rest = T - b.uu / (nu * nu);
      if (rest <= 0) continue;
      // b.vv/N_v² + 2 b.uv/(nu N_v) = rest, solved for 1/N_v.
      const double p = b.uv / nu;
      const double x = b.vv > 0 ? (-p + std::sqrt(p * p + b.vv * rest)) / b.vv
                                : (p > 0 ? rest / (2 * p) : INFINITY);
      best = std::min(best, nu * std::max(1.0, 1.0 / x));
    }
    CHECK(d.realU * d.realV <= best * (1 + 1e-3));
  }
  CHECK_THROWS_AS(divisionsFromBounds({}, 0.0, 10), std::invalid_argument);
  CHECK_THROWS_AS(divisionsFromBounds({}, NAN, 10), std::invalid_argument);
}

TEST_CASE("Division: bad input is refused with a reason", "[division]") {
  RationalBezierPatch p = quarterCylinder(1.0, 1.0);
  p.degreeU = 8;
  CHECK_THROWS_WITH(validateDivisionInput(p, DivisionMethod::Split),
                    Catch::Contains("outside 1..7"));
  p = quarterCylinder(1.0, 1.0);
  p.cpw.pop_back();
  CHECK_THROWS_WITH(validateDivisionInput(p, DivisionMethod::Split),
                    Catch::Contains("control points"));
  p = quarterCylinder(1.0, 1.0);
  p.cpw[2].x = NAN;
  CHECK_THROWS_WITH(validateDivisionInput(p, DivisionMethod::Split),
                    Catch::Contains("non-finite"));
  p = quarterCylinder(1.0, 1.0);
  for (glm::dvec4& h : p.cpw) h.w = 0.0;
  CHECK_THROWS_WITH(validateDivisionInput(p, DivisionMethod::Split),
                    Catch::Contains("every weight is zero"));
  p = quarterCylinder(1.0, 1.0);
  p.cpw[0].w = -1.0;
  CHECK_THROWS_WITH(validateDivisionInput(p, DivisionMethod::PaperSplit),
                    Catch::Contains("≥ 0"));
  CHECK_THROWS_AS(parseDivisionMethod("fast"), std::invalid_argument);
  CHECK(parseDivisionMethod("split") == DivisionMethod::Split);
  CHECK(parseDivisionMethod("cellwise") == DivisionMethod::CellWise);
  CHECK(std::string(divisionMethodName(DivisionMethod::CellWise)) == "cellwise");
}
