// FaceSurface::points on batches across pieces' sides (no OCCT: the IDF version of this check is
// in test_cad_import.cpp): each uv's piece found from the cells of the batch's box must be
// pieceAt's, so every point is point()'s double, on the sides themselves, past the face's
// domain (clamped), and where the pieces' grid has a hole (pieceAt's nearest rectangle).
#include <catch2/catch.hpp>

#include <cstring>
#include <vector>

#include "trim/face_surface.h"
#include "trimmed_models.h"

using namespace tessera;
using namespace tessera::test;

namespace {

size_t expectPointsBits(const TrimmedFace& face, glm::dvec2 lo, glm::dvec2 hi, int n) {
  const FaceSurface surface(face);
  std::vector<glm::dvec2> uvs;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) uvs.push_back(lo + (hi - lo) * glm::dvec2(i, j) / double(n));
  std::vector<glm::dvec3> batch(uvs.size());
  surface.points(uvs.data(), uvs.size(), batch.data());
  for (size_t k = 0; k < uvs.size(); ++k) {
    const glm::dvec3 one = surface.point(uvs[k]);
    INFO(uvs[k].x << ", " << uvs[k].y);
    REQUIRE(std::memcmp(&one, &batch[k], sizeof one) == 0);
  }
  return uvs.size();
}

}  // namespace

TEST_CASE("FaceSurface::points across pieces' sides gives point()'s doubles", "[trim]") {
  const TrimmedFace cylinder = fourPieceCylinderSide();
  const double quarter = kPi / 2;
  // Grids whose points fall on the sides u = kπ/2 exactly, across two and four pieces, and past
  // the domain's ends.
  CHECK(expectPointsBits(cylinder, {0, 0}, {2 * quarter, 1}, 8) == 81);
  CHECK(expectPointsBits(cylinder, {0, 0}, {4 * quarter, 1}, 16) == 289);
  CHECK(expectPointsBits(cylinder, {-0.5, -0.25}, {4 * quarter + 0.5, 1.25}, 12) == 169);
  // A hole in the grid of pieces: three of the four quarters, so some uvs fall in no piece.
  TrimmedFace holed = cylinder;
  holed.pieces.erase(holed.pieces.begin() + 2);
  CHECK(expectPointsBits(holed, {0.1, 0}, {4 * quarter - 0.1, 1}, 10) == 121);
  CHECK(expectPointsBits(holed, {0.1, 0}, {2 * quarter, 1}, 10) == 121);
}
