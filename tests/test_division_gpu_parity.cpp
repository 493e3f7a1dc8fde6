// GPU division counts (shaders/division_count.comp.glsl) against the fp32 mirror (bit for bit
// on lavapipe; other drivers' mirror differences are printed) and against the double reference (counts equal, or one apart only where the
// reference's real-valued count lies within the band of docs/rational_division.md).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <iostream>
#include <random>

#include "division/count.h"
#include "division/counter.h"
#include "division_samples.h"
#include "gpu_test_context.h"
#include "experiments/rational_samples.h"

using namespace tessera;
using namespace tessera::test;

namespace {

// Relative band around an integer within which fp32 may round the count the other way.
constexpr double kCountBand = 1e-3;

bool nearInteger(double real) {
  return std::abs(real - std::round(real)) <= kCountBand * real;
}

std::vector<RationalBezierPatch> parityPatches() {
  std::mt19937 rng(905);
  std::vector<RationalBezierPatch> patches;
  for (int trial = 0; trial < 3000; ++trial) {
    const int n = 1 + trial % 7, m = 1 + (trial / 7) % 4;
    const WeightKind kind = static_cast<WeightKind>((trial / 28) % 4);
    patches.push_back(toPatch(randomNet(n, m, kind, rng)));
  }
  // The surfaces of the comparison table, in world space and as seen by its cameras.
  for (const SampleView& view : zeroWeightViews(false)) {
    patches.push_back(view.patch);
    patches.push_back(screenSpacePatch(view.patch, view.camera));
  }
  return patches;
}

bool sameBits(const gpu::DivisionResult& a, const gpu::DivisionResult& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

}  // namespace

TEST_CASE("Division counts: Vulkan equals the fp32 mirror bit for bit and the double reference "
          "within the band",
          "[division][gpu]") {
  const std::vector<RationalBezierPatch> patches = parityPatches();
  DivisionOptions options;
  options.tolerance = 0.01;
  options.maxPerDirection = 4096;
  const DivisionBatch batch = packDivisionBatch(patches);
  const auto gpuResults = makeVulkanDivisionCounter(gpuContext())->count(batch, options);
  const auto mirrorResults = makeMirrorDivisionCounter()->count(batch, options);
  requireValidationClean();
  REQUIRE(gpuResults.size() == patches.size());

  size_t mirrorMismatches = 0, statusMismatches = 0, offByOneInBand = 0, outOfBand = 0,
         compared = 0, unbounded = 0;
  int maxCountDiff = 0;
  double maxBoundRel = 0.0;
  for (size_t p = 0; p < patches.size(); ++p) {
    mirrorMismatches += !sameBits(gpuResults[p], mirrorResults[p]);
    const Divisions ref = patchDivisions(patches[p], options);
    const gpu::DivisionResult& g = gpuResults[p];
    const bool refUnbounded = ref.status == DivisionStatus::Unbounded;
    if (refUnbounded != (g.status == gpu::kDivisionUnbounded)) {
      ++statusMismatches;
      UNSCOPED_INFO("patch " << p << ": reference " << divisionStatusName(ref.status)
                             << ", GPU status " << g.status);
      continue;
    }
    if (refUnbounded) {
      ++unbounded;
      CHECK(g.nu == uint32_t(options.maxPerDirection));
      continue;
    }
    ++compared;
    const double refB[3] = {ref.bounds.uu, ref.bounds.uv, ref.bounds.vv};
    const float gpuB[3] = {g.uu, g.uv, g.vv};
    for (int k = 0; k < 3; ++k) {
      const double scale = std::max({refB[0], refB[1], refB[2], 1e-30});
      maxBoundRel = std::max(maxBoundRel, std::abs(gpuB[k] - refB[k]) / scale);
    }
    const int refCounts[2] = {ref.nu, ref.nv}, gpuCounts[2] = {int(g.nu), int(g.nv)};
    const double reals[2] = {ref.realU, ref.realV};
    for (int d = 0; d < 2; ++d) {
      const int diff = std::abs(refCounts[d] - gpuCounts[d]);
      maxCountDiff = std::max(maxCountDiff, diff);
      if (diff == 0) continue;
      if (diff == 1 && nearInteger(reals[d])) {
        ++offByOneInBand;
      } else {
        ++outOfBand;
        UNSCOPED_INFO("patch " << p << " direction " << d << ": reference " << refCounts[d]
                               << " (real " << reals[d] << "), GPU " << gpuCounts[d]);
      }
    }
  }
  std::cout << "division parity: " << patches.size() << " patches (" << compared
            << " compared, " << unbounded << " unbounded in both), mirror mismatches "
            << mirrorMismatches << ", status mismatches " << statusMismatches
            << ", off by one within the band " << kCountBand << ": " << offByOneInBand
            << ", outside: " << outOfBand << ", max count difference " << maxCountDiff
            << ", max relative bound difference " << maxBoundRel << "\n";
  if (test::exactMirrorArithmetic()) CHECK(mirrorMismatches == 0);
  CHECK(statusMismatches == 0);
  CHECK(outOfBand == 0);
  CHECK(maxCountDiff <= 1);
  CHECK(maxBoundRel < 1e-3);
  CHECK(compared >= 2500);
}

TEST_CASE("Division counts of curves (appendDivisionCurves): Vulkan equals the fp32 mirror bit "
          "for bit and the double curveDivisions within the band",
          "[division][gpu]") {
  // The first row of every parity patch (degrees 1..7, every weight kind) as a curve.
  std::vector<RationalBezierCurve> curves;
  for (const RationalBezierPatch& patch : parityPatches()) {
    RationalBezierCurve curve;
    curve.degree = patch.degreeU;
    for (int i = 0; i <= patch.degreeU; ++i) curve.cpw.push_back(patch.at(i, 0));
    curves.push_back(curve);
  }
  DivisionOptions options;
  options.tolerance = 0.01;
  options.maxPerDirection = 4096;
  DivisionBatch batch;
  appendDivisionCurves(batch, curves);
  const auto gpuResults = makeVulkanDivisionCounter(gpuContext())->count(batch, options);
  const auto mirrorResults = makeMirrorDivisionCounter()->count(batch, options);
  requireValidationClean();
  REQUIRE(gpuResults.size() == curves.size());
  size_t mirrorMismatches = 0, statusMismatches = 0, outOfBand = 0, compared = 0, nvNotOne = 0;
  int maxCountDiff = 0;
  for (size_t c = 0; c < curves.size(); ++c) {
    mirrorMismatches += !sameBits(gpuResults[c], mirrorResults[c]);
    const Divisions ref = curveDivisions(curves[c], options);
    const gpu::DivisionResult& g = gpuResults[c];
    if ((ref.status == DivisionStatus::Unbounded) != (g.status == gpu::kDivisionUnbounded)) {
      ++statusMismatches;
      continue;
    }
    if (ref.status == DivisionStatus::Unbounded) continue;
    ++compared;
    nvNotOne += g.nv != 1;
    const int diff = std::abs(ref.nu - int(g.nu));
    maxCountDiff = std::max(maxCountDiff, diff);
    if (diff > 1 || (diff == 1 && !nearInteger(ref.realU))) {
      ++outOfBand;
      UNSCOPED_INFO("curve " << c << ": reference " << ref.nu << " (real " << ref.realU
                             << "), GPU " << g.nu);
    }
  }
  std::cout << "curve division parity: " << curves.size() << " curves (" << compared
            << " compared), mirror mismatches " << mirrorMismatches << ", status mismatches "
            << statusMismatches << ", outside the band: " << outOfBand
            << ", max count difference " << maxCountDiff << "\n";
  if (test::exactMirrorArithmetic()) CHECK(mirrorMismatches == 0);
  CHECK(statusMismatches == 0);
  CHECK(outOfBand == 0);
  CHECK(maxCountDiff <= 1);
  CHECK(nvNotOne == 0);
  CHECK(compared >= 2500);
  RationalBezierCurve bad;
  bad.degree = 0;
  bad.cpw = {glm::dvec4(0, 0, 0, 1)};
  DivisionBatch refused;
  CHECK_THROWS_WITH(appendDivisionCurves(refused, {bad}), Catch::Contains("curve 0"));
}
