// The reduction's row product (curve_product.h) in fp32: the CPU mirror and the Vulkan shader
// (shaders/reduction_apply.comp.glsl) against double, bit for bit with each other on lavapipe,
// and the whole reduction with the product on the GPU against the CPU-only one.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "reduction/banded_oslo.h"
#include "reduction/curve_product.h"
#include "gpu_test_context.h"
#include "bspline/knots.h"
#include "reduction/fast.h"
#include "experiments/synthetic_surfaces.h"

using namespace tessera;

namespace {

// A⁺ of a 90-point curve reduced to every third interior knot (the cut at 1e-10 the reduction
// uses), and the 70 curves of a synthetic last's v direction as data.
struct ProductCase {
  BandMatrix pinv;
  std::vector<glm::dvec3> curves;
  int curveCount = 0;
};

ProductCase productCase() {
  const BSplineSurface s = syntheticLast(70, 90);
  std::vector<double> x;
  for (size_t k = 0; k < s.knotsV.size(); ++k) {
    if (k <= 3 || k >= static_cast<size_t>(s.countV) || k % 3 == 0) x.push_back(s.knotsV[k]);
  }
  ProductCase c;
  c.pinv = pseudoInverseBand(osloBand(3, x, s.knotsV), 3, 1e-10);
  c.curves = s.cp;  // row-major, i along u: row i is the v-curve i
  c.curveCount = s.countU;
  return c;
}

// The per-point bound stated in curve_product.h, and how far each point is from double.
struct BoundCheck {
  double worst = 0.0;       // largest |fp32 − double| coordinate difference
  double worstRatio = 0.0;  // largest difference / bound
};

BoundCheck againstDouble(const ProductCase& c, const std::vector<glm::dvec3>& fp32) {
  const std::vector<glm::dvec3> exact = applyBandToCurves(c.pinv, c.curves, c.curveCount);
  REQUIRE(fp32.size() == exact.size());
  BoundCheck r;
  for (int curve = 0; curve < c.curveCount; ++curve) {
    const glm::dvec3* pts = c.curves.data() + static_cast<size_t>(curve) * c.pinv.cols;
    for (int i = 0; i < c.pinv.rows; ++i) {
      double absWeights = 0.0, extent = 0.0;
      for (int t = 0; t < c.pinv.width(i); ++t) {
        absWeights += std::abs(c.pinv.values[c.pinv.offset[static_cast<size_t>(i)] + static_cast<size_t>(t)]);
        const glm::dvec3 d = pts[c.pinv.first[static_cast<size_t>(i)] + t] - pts[0];
        extent = std::max({extent, std::abs(d.x), std::abs(d.y), std::abs(d.z)});
      }
      const double bound = 2.0 * (c.pinv.width(i) + 1) * std::ldexp(1.0, -24) * absWeights * extent;
      const size_t at = static_cast<size_t>(curve) * c.pinv.rows + static_cast<size_t>(i);
      for (int axis = 0; axis < 3; ++axis) {
        const double diff = std::abs(fp32[at][axis] - exact[at][axis]);
        r.worst = std::max(r.worst, diff);
        r.worstRatio = std::max(r.worstRatio, diff / bound);
      }
    }
  }
  return r;
}

}  // namespace

TEST_CASE("The fp32 mirror of the row product stays within its bound of double", "[reduce]") {
  const ProductCase c = productCase();
  const std::vector<glm::dvec3> fp32 = makeMirrorCurveProduct()->apply(c.pinv, c.curves, c.curveCount);
  const BoundCheck r = againstDouble(c, fp32);
  WARN("mirror vs double: max coordinate difference " << r.worst << " mm, "
                                                      << r.worstRatio << " of the bound");
  CHECK(r.worstRatio <= 1.0);
  CHECK(r.worst <= 1e-4);
  CHECK_THROWS_AS(makeMirrorCurveProduct()->apply(c.pinv, c.curves, c.curveCount + 1),
                  std::invalid_argument);
}

TEST_CASE("Row product on Vulkan: bit-exact with the fp32 mirror, within the fp32 bound of double",
          "[gpu][reduce]") {
  auto& context = test::gpuContext();
  const ProductCase c = productCase();
  auto gpu = makeVulkanCurveProduct(context);
  const std::vector<glm::dvec3> onGpu = gpu->apply(c.pinv, c.curves, c.curveCount);
  const std::vector<glm::dvec3> onMirror =
      makeMirrorCurveProduct()->apply(c.pinv, c.curves, c.curveCount);
  REQUIRE(onGpu.size() == onMirror.size());
  size_t mismatches = 0;
  double mirrorDiff = 0.0;
  for (size_t i = 0; i < onGpu.size(); ++i) {
    for (int axis = 0; axis < 3; ++axis) {
      const double d = std::abs(onGpu[i][axis] - onMirror[i][axis]);
      mirrorDiff = std::max(mirrorDiff, d);
      if (d != 0.0) ++mismatches;
    }
  }
  const BoundCheck r = againstDouble(c, onGpu);
  WARN(gpu->name() << ": " << onGpu.size() << " points; vs mirror " << mismatches
                   << " coordinates differ (max " << mirrorDiff << "); vs double max "
                   << r.worst << " mm = " << r.worstRatio << " of the fp32 bound");
  if (context.info().isLavapipe()) CHECK(mismatches == 0);
  CHECK(r.worstRatio <= 1.0);
  // A second, smaller product reuses the buffers.
  const ProductCase small{c.pinv, std::vector<glm::dvec3>(c.curves.begin(), c.curves.begin() + 3 * c.pinv.cols), 3};
  const auto again = gpu->apply(small.pinv, small.curves, 3);
  CHECK(std::equal(again.begin(), again.end(), onGpu.begin()));
  test::requireValidationClean();
}

TEST_CASE("The reduction with the row product on Vulkan matches the CPU-only reduction",
          "[gpu][reduce]") {
  auto& context = test::gpuContext();
  const BSplineSurface s = syntheticLast(120, 140);
  ReductionOptions o;
  o.threshold = 0.05;
  const ReductionResult cpu = reduceSurface(s, o);
  auto gpu = makeVulkanCurveProduct(context);
  const ReductionResult onGpu = reduceSurface(s, o, gpu.get());
  // The first pass decides in double either way; its final net (fp32 on the GPU) feeds the
  // second pass, whose decisions may only differ where an error lands within fp32 noise of
  // the target.
  CHECK(onGpu.passes[0].removed == cpu.passes[0].removed);
  CHECK(onGpu.surface.knotsV == cpu.surface.knotsV);
  const DeviationStats d = netDeviation(s, onGpu.surface);
  CHECK(d.mean == Approx(onGpu.error.mean).margin(1e-12));
  CHECK(d.mean <= o.threshold + 1e-5);  // fp32 of the final nets: within 1e-5 mm
  double diff = -1.0;
  if (onGpu.surface.knotsU == cpu.surface.knotsU) {
    diff = 0.0;
    for (size_t i = 0; i < cpu.surface.cp.size(); ++i) {
      for (int axis = 0; axis < 3; ++axis) diff = std::max(diff, std::abs(cpu.surface.cp[i][axis] - onGpu.surface.cp[i][axis]));
    }
    CHECK(diff <= 1e-4);
  }
  WARN("GPU-applied vs CPU-only on 120 x 140 at 0.05: kept " << onGpu.keptControlPoints << " vs "
       << cpu.keptControlPoints << ", max control point difference " << diff << " mm");
  CHECK(std::abs(onGpu.keptControlPoints - cpu.keptControlPoints) <= cpu.keptControlPoints / 50);
  test::requireValidationClean();
}
