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

TEST_CASE("gap refinement: the geometric check answers as the full measure", "[trim]") {
  const TrimmedFace face = quarterTorusFace();
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
