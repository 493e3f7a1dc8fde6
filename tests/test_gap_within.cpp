// The gap refinement's geometric check (trim/detail/gap_refine.h, interpolationWithin): it
// skips the closest-point search of samples already within the limit of their target, and must
// answer exactly as the full measure, interpolationDistance(…) ≤ limit, including at limits
// a rounding away from the measured distance.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "trim/detail/gap_refine.h"
#include "trim/face_surface.h"
#include "trimmed_models.h"

using namespace tessera;
using namespace tessera::test;
using trim_detail::FaceVertex;

namespace {

// A quarter of a torus (tube radius 1 round a circle of radius 2): a rational 2 × 2 piece whose
// parametrisation slides along the surface, so triangles measure over the limit parametrically
// and within it geometrically, the case the check exists for.
TrimmedFace quarterTorus() {
  const double w = std::sqrt(0.5);
  const glm::dvec2 around[3] = {{1, 0}, {1, 1}, {0, 1}};     // the big circle's quarter
  const glm::dvec2 profile[3] = {{3, 0}, {3, 1}, {2, 1}};   // (distance from the axis, height)
  const double weight[3] = {1, w, 1};
  BezierPatch patch;
  patch.degreeU = 2, patch.degreeV = 2;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      patch.cp.push_back({profile[j].x * around[i].x, profile[j].x * around[i].y, profile[j].y});
      patch.weights.push_back(weight[i] * weight[j]);
    }
  return faceOf(patch, {}, false, 0);
}

}  // namespace

TEST_CASE("gap refinement: the geometric check answers as the full measure", "[trim]") {
  const TrimmedFace face = quarterTorus();
  const FaceSurface surface(face);
  std::mt19937 random(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0), size(0.05, 0.6);
  size_t skippedSome = 0, over = 0, within = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const glm::dvec2 origin(unit(random) * 0.4, unit(random) * 0.4);
    const double s = size(random);
    std::vector<FaceVertex> vs;
    for (glm::dvec2 corner : {glm::dvec2(0, 0), glm::dvec2(1, unit(random) * 0.3),
                              glm::dvec2(unit(random), 1)}) {
      const glm::dvec2 uv = origin + s * corner;
      vs.push_back({uv, surface.point(uv), -1});
    }
    const std::array<uint32_t, 3> t{0, 1, 2};
    const double full = trim_detail::interpolationDistance(surface, vs, t, 8);
    const double parametric = trim_detail::interpolationDeviation(surface, vs, t, 8);
    if (parametric > full) ++skippedSome;
    for (double limit : {0.5 * full, full * (1 - 1e-15), full, full * (1 + 1e-15), 2 * full,
                         0.5 * parametric, parametric, 1e-4, 1e-3, 1e-2}) {
      const bool expected = full <= limit;
      CHECK(trim_detail::interpolationWithin(surface, vs, t, 8, limit) == expected);
      (expected ? within : over)++;
    }
  }
  // Both answers seen, and triangles where the parametric error exceeds the distance (where
  // the search matters).
  CHECK(over > 100);
  CHECK(within > 100);
  CHECK(skippedSome > 50);
}
