// "Never under-divides": over random rational curves and patches (fixed seeds) with zero and
// negative weights, the bounds of the split, subdivided, cellwise, directional and direct
// methods are never below the sampled maximum of ‖c''‖ (‖S_uu‖, ‖S_uv‖, ‖S_vv‖), and the
// uniform grid of the computed counts deviates at most TOL from the surface (host/division/count.h, docs/rational_division.md).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <random>

#include "division/count.h"
#include "division/deviation.h"
#include "division_samples.h"
#include "geometry/homogeneous_net.h"
#include "sweep_share.h"

using namespace tessera;
using namespace tessera::test;

namespace {

struct Tally {
  int tried = 0, checked = 0, unbounded = 0, capped = 0, withZero = 0, withNegative = 0;
  // cellwise and directional: their faces and the subdivided ones
  long long faces = 0, subdividedFaces = 0;
  double worstBoundRatio = INFINITY;    // min over cases of bound / sampled max (must be ≥ 1)
  double worstDeviationRatio = 0.0;     // max over cases of measured deviation / TOL (≤ 1)
};

// Methods that search below the subdivided grid.
bool searchesCells(DivisionMethod method) {
  return method == DivisionMethod::CellWise || method == DivisionMethod::Directional ||
         method == DivisionMethod::Direct;
}

void checkPatch(const HomogeneousNet& net, DivisionMethod method, double tol, Tally& t) {
  ++t.tried;
  DivisionOptions o;
  o.method = method;
  o.tolerance = tol;
  o.maxPerDirection = 400;
  const Divisions d = patchDivisions(toPatch(net), o);
  if (searchesCells(method)) {
    // Searched below the subdivided grid: never more faces, the same status.
    o.method = DivisionMethod::Subdivided;
    const Divisions s = patchDivisions(toPatch(net), o);
    CHECK(d.status == s.status);
    CHECK(d.divisionNumber() <= s.divisionNumber());
    t.faces += d.divisionNumber();
    t.subdividedFaces += s.divisionNumber();
  }
  if (d.status == DivisionStatus::Unbounded) {
    ++t.unbounded;
    // Unbounded must mean it: w really vanishes or changes sign somewhere, or the q×q pieces
    // could not show it does not. At least the grid of the cap must not pass silently.
    CHECK(d.nu == o.maxPerDirection);
    return;
  }
  const SampledSecondDerivatives s = sampledSecondDerivatives(net, 16);
  auto ratio = [](double bound, double sampled) {
    return sampled > 1e-12 ? bound / sampled : INFINITY;
  };
  const double r = std::min({ratio(d.bounds.uu, s.uu), ratio(d.bounds.uv, s.uv),
                             ratio(d.bounds.vv, s.vv)});
  t.worstBoundRatio = std::min(t.worstBoundRatio, r);
  CHECK(r >= 1.0 - 1e-9);
  if (d.status == DivisionStatus::Capped) {
    ++t.capped;
    return;
  }
  const double dev = uniformGridDeviation(net, d.nu, d.nv, {3, 18});
  t.worstDeviationRatio = std::max(t.worstDeviationRatio, dev / tol);
  CHECK(dev <= tol);
  ++t.checked;
  t.withZero += hasZeroWeight(net);
  t.withNegative += hasNegativeWeight(net);
}

// `count` random patches of bidegree (1..3, 1..3), the four weight kinds in turn.
Tally runPatches(uint32_t seed, int count, DivisionMethod method, double tol) {
  std::mt19937 rng(seed);
  Tally t;
  for (int trial = 0; trial < count; ++trial) {
    const int n = 1 + trial % 3, m = 1 + (trial / 3) % 3;
    const WeightKind kind = static_cast<WeightKind>((trial / 9) % 4);
    const HomogeneousNet net = randomNet(n, m, kind, rng);
    INFO("trial " << trial);
    checkPatch(net, method, tol, t);
  }
  WARN(divisionMethodName(method)
       << ": " << t.tried << " patches, " << t.checked << " grids measured (" << t.withZero
       << " with zero weights, " << t.withNegative << " with negative ones), " << t.unbounded
       << " unbounded, " << t.capped << " capped; smallest bound/sampled " << t.worstBoundRatio
       << ", largest deviation/TOL " << t.worstDeviationRatio);
  if (searchesCells(method))
    WARN(divisionMethodName(method) << " faces " << t.faces << " vs subdivided " << t.subdividedFaces << " ("
                           << double(t.faces) / double(std::max(1LL, t.subdividedFaces)) << ")");
  return t;
}

// The share of these random sweeps a run takes: all in Release; under the sanitizers half the
// sweep share (sweep_share.h), an eighth: every patch takes the paths the others take, and
// ASan makes each ~10x dearer. The floor of 36 keeps each of the 36 bidegree and weight-kind
// classes.
double patchShare() { return test::sweepShare() == 1.0 ? 1.0 : 0.5 * test::sweepShare(); }
int swept(int count) { return std::max(36, int(count * patchShare())); }

// Enough grids measured, enough of them with zero and with negative weights.
void checkCoverage(const Tally& t, int checked, int withEach) {
  CHECK(t.checked >= checked);
  CHECK(t.withZero >= withEach);
  CHECK(t.withNegative >= withEach);
}

// The same for a sweep of swept(count) patches: the full figures at share 1, else the share of
// them with a tenth to spare (a part of the sequence need not hold its exact mix).
void checkSweptCoverage(const Tally& t, int checked, int withEach) {
  const double share = patchShare();
  if (share == 1.0) return checkCoverage(t, checked, withEach);
  checkCoverage(t, int(checked * share * 0.9), int(withEach * share * 0.9));
}

}  // namespace

TEST_CASE("Division never under-divides: 1,200 random rational patches, split method",
          "[division]") {
  checkSweptCoverage(runPatches(20260523, swept(1200), DivisionMethod::Split, 0.05), 1000, 300);
}

TEST_CASE("Division never under-divides: 300 random rational patches, subdivided method",
          "[division]") {
  checkCoverage(runPatches(77, 300, DivisionMethod::Subdivided, 0.02), 250, 60);
}

TEST_CASE("Division never under-divides: 1,050 random rational patches, cellwise method",
          "[division]") {
  const Tally t = runPatches(9151, swept(1050), DivisionMethod::CellWise, 0.25);
  checkSweptCoverage(t, 1000, 300);
  CHECK(t.faces < t.subdividedFaces);  // the per-cell bounds do pay somewhere
}

TEST_CASE("Division never under-divides: 1,050 random rational patches, directional method",
          "[division]") {
  const Tally t = runPatches(5150, swept(1050), DivisionMethod::Directional, 0.25);
  checkSweptCoverage(t, 1000, 300);
  CHECK(t.faces < t.subdividedFaces);
}

TEST_CASE("Division never under-divides: 1,050 random rational patches, direct method",
          "[division]") {
  const Tally t = runPatches(6160, swept(1050), DivisionMethod::Direct, 0.25);
  checkSweptCoverage(t, 1000, 300);
  CHECK(t.faces < t.subdividedFaces);
}

TEST_CASE("Division never under-divides: ‖c''‖ bound over 1,200 random curves of degree 1..7",
          "[division]") {
  std::mt19937 rng(4242);
  int bounded = 0, zeros = 0, negatives = 0;
  double worst[2] = {INFINITY, INFINITY};
  for (int trial = 0; trial < 1200; ++trial) {
    const int degree = 1 + trial % kMaxDegree;
    const WeightKind kind = static_cast<WeightKind>((trial / 7) % 4);
    const HomogeneousNet net = randomNet(degree, 0, kind, rng);
    const SampledSecondDerivatives s = sampledSecondDerivatives(net, 400);
    int m = 0;
    for (DivisionMethod method : {DivisionMethod::Split, DivisionMethod::Subdivided}) {
      DivisionOptions o;
      o.method = method;
      const SecondDerivativeBounds b =
          secondDerivativeBounds(RationalBezierCurve{degree, net.c}, o);
      if (b.bounded && s.uu > 0) {
        INFO("trial " << trial << " " << divisionMethodName(method) << ": bound " << b.uu
                      << ", sampled " << s.uu);
        CHECK(b.uu >= s.uu * (1 - 1e-9));
        worst[m] = std::min(worst[m], b.uu / s.uu);
        if (method == DivisionMethod::Split) {
          ++bounded;
          zeros += hasZeroWeight(net);
          negatives += hasNegativeWeight(net);
        }
      }
      ++m;
    }
  }
  WARN("curves: " << bounded << " bounded by split (" << zeros << " with zero weights, "
                  << negatives << " with negative ones); smallest bound/sampled: split "
                  << worst[0] << ", subdivided " << worst[1]);
  CHECK(bounded >= 1000);
  CHECK(zeros >= 300);
  CHECK(negatives >= 300);
}
