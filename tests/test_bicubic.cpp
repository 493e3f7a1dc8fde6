// The bicubic fast path (host/geometry/bicubic.h) against the general evaluator (host/geometry/bezier.h).
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <stdexcept>

#include "geometry/bezier.h"
#include "geometry/bicubic.h"

using namespace tessera;

namespace {

using Field = glm::dvec3 SurfaceDerivatives::*;
const struct {
  const char* name;
  Field field;
} kFields[] = {{"p", &SurfaceDerivatives::p},       {"pu", &SurfaceDerivatives::pu},
               {"pv", &SurfaceDerivatives::pv},     {"puu", &SurfaceDerivatives::puu},
               {"puv", &SurfaceDerivatives::puv},   {"pvv", &SurfaceDerivatives::pvv},
               {"puuu", &SurfaceDerivatives::puuu}, {"puuv", &SurfaceDerivatives::puuv},
               {"puvv", &SurfaceDerivatives::puvv}, {"pvvv", &SurfaceDerivatives::pvvv}};

}  // namespace

TEST_CASE("Bicubic fast path equals the general path to ~1e-14 relative", "[bicubic]") {
  std::mt19937 rng(31415);
  std::uniform_real_distribution<double> coord(-1.0, 1.0), offset(-100.0, 100.0);
  double worst = 0;
  for (int trial = 0; trial < 50; ++trial) {
    // Far from the origin too: relative error must not grow with the offset.
    const glm::dvec3 shift =
        trial % 2 ? glm::dvec3(offset(rng), offset(rng), offset(rng)) : glm::dvec3(0.0);
    BezierPatch patch{3, 3, {}};
    BicubicNet net;
    for (int k = 0; k < 16; ++k) {
      net[k] = shift + glm::dvec3(coord(rng), coord(rng), coord(rng));
      patch.cp.push_back(net[k]);
    }
    for (int a = 0; a <= 8; ++a)
      for (int b = 0; b <= 8; ++b) {
        const double u = a / 8.0, v = b / 8.0;
        const SurfaceDerivatives general = patchDerivatives(patch, u, v);
        const SurfaceDerivatives fast = bicubicDerivatives(net, u, v);
        const SurfaceDerivatives fromPatch = bicubicDerivatives(patch, u, v);
        for (const auto& f : kFields) {
          INFO("trial " << trial << " at (" << u << ", " << v << "): " << f.name);
          const glm::dvec3 g = general.*f.field;
          // Relative to the field's size, or to the net's extent (coordinates within ±1 of
          // the shift) for a derivative near zero: it is a difference of terms of that size.
          const double netExtent = 1.0;
          const double err = glm::distance(fast.*f.field, g) / std::max(glm::length(g), netExtent);
          worst = std::max(worst, err);
          CHECK(err <= 1e-14);
          CHECK(fromPatch.*f.field == fast.*f.field);
        }
      }
  }
  INFO("largest relative difference " << worst);
  CHECK(worst > 0.0);  // the two paths really are different code
}

TEST_CASE("Bicubic fast path: collapsed edge has exactly zero tangent, bad input throws",
          "[bicubic]") {
  BicubicNet net;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      net[4 * i + j] = j == 0 ? glm::dvec3(0.3, -0.7, 2.1) : glm::dvec3(i, j, i * j) / 3.0;
  for (double u : {0.0, 0.3, 0.5, 1.0}) {
    const SurfaceDerivatives d = bicubicDerivatives(net, u, 0.0);
    CHECK(d.pu == glm::dvec3(0.0));
    CHECK(d.puu == glm::dvec3(0.0));
    CHECK(d.puuu == glm::dvec3(0.0));
  }
  CHECK_THROWS_AS(bicubicDerivatives(BezierPatch{3, 2, std::vector<glm::dvec3>(12)}, 0.5, 0.5),
                  std::invalid_argument);
  CHECK_THROWS_AS(bicubicDerivatives(BezierPatch{3, 3, std::vector<glm::dvec3>(12)}, 0.5, 0.5),
                  std::invalid_argument);
}
