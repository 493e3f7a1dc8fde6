// The gap refinement's shared side samples (trim/detail/gap_refine.h,
// sampledDeviationsSharingSides): the samples inside a side two triangles share are taken once,
// and every triangle's measures must be sampledDeviations' doubles, bit for bit, whichever
// corners the side joins in each triangle, on one-piece and multi-piece faces, with trim points
// off the surface, and at a subdivision that is not a power of two (no sharing).
#include <catch2/catch.hpp>

#include <random>

#include "trim/detail/gap_refine.h"
#include "trim/face_surface.h"
#include "trimmed_models.h"

using namespace tessera;
using namespace tessera::test;
using trim_detail::FaceVertex;

namespace {

// An m × m grid of vertices over [lo, hi], two triangles a cell, each triangle's corners rotated
// by a different amount (so a shared side is (t0, t1) in one triangle and (t1, t2) or (t2, t0)
// in the other); every third vertex a trim point lifted off the surface.
void gridMesh(const FaceSurface& surface, glm::dvec2 lo, glm::dvec2 hi, int m,
              std::vector<FaceVertex>& vs, std::vector<std::array<uint32_t, 3>>& triangles) {
  std::mt19937 random(34);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= m; ++j) {
      const glm::dvec2 step = (hi - lo) / double(m);
      glm::dvec2 uv = lo + step * glm::dvec2(i, j);
      if (i > 0 && i < m && j > 0 && j < m) uv += step * glm::dvec2(jitter(random), jitter(random));
      const bool trim = (i + j) % 3 == 0;
      vs.push_back({uv, surface.point(uv) + (trim ? glm::dvec3(1e-3, -2e-3, 5e-4) : glm::dvec3(0)),
                    trim ? int64_t(vs.size()) : -1});
    }
  const auto id = [&](int i, int j) { return uint32_t(i * (m + 1) + j); };
  int turn = 0;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      for (std::array<uint32_t, 3> t : {std::array<uint32_t, 3>{id(i, j), id(i + 1, j), id(i + 1, j + 1)},
                                        std::array<uint32_t, 3>{id(i, j), id(i + 1, j + 1), id(i, j + 1)}}) {
        const int r = turn++ % 3;
        triangles.push_back({t[size_t(r)], t[size_t((r + 1) % 3)], t[size_t((r + 2) % 3)]});
      }
    }
}

size_t expectSameBits(const TrimmedFace& face, glm::dvec2 lo, glm::dvec2 hi, int n) {
  const FaceSurface surface(face);
  std::vector<FaceVertex> vs;
  std::vector<std::array<uint32_t, 3>> triangles;
  gridMesh(surface, lo, hi, 7, vs, triangles);
  const std::vector<trim_detail::SampledDeviations> shared =
      trim_detail::sampledDeviationsSharingSides(surface, vs, triangles, n);
  REQUIRE(shared.size() == triangles.size());
  size_t curved = 0;
  for (size_t k = 0; k < triangles.size(); ++k) {
    const trim_detail::SampledDeviations alone =
        trim_detail::sampledDeviations(surface, vs, triangles[k], n);
    CHECK(shared[k].interpolation == alone.interpolation);
    CHECK(shared[k].parametric == alone.parametric);
    if (alone.interpolation > 1e-6) ++curved;
  }
  return curved;
}

}  // namespace

TEST_CASE("gap refinement: shared side samples give each triangle's own measures", "[trim]") {
  // Measures that could differ: most triangles bend away from their chords.
  for (int n : {8, 4, 6})
    CHECK(expectSameBits(quarterTorusFace(), {0.05, 0.1}, {0.95, 0.9}, n) > 80);
  // Triangles across the pieces' sides (points() per uv) and within one piece.
  for (int n : {8, 6})
    CHECK(expectSameBits(fourPieceCylinderSide(), {0.3, 0.0}, {5.9, 1.0}, n) > 80);
}
