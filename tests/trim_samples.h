// Hand-made trimmed faces for the trim classifier tests: a square with a circular hole, a
// star, thin slivers, a square whose sides lie on dyadic node sides, a face without loops and
// a circle far from the origin; and random node rectangles over their pieces.
#pragma once
#include <cstdint>
#include <vector>

#include "trim/trim_classifier.h"

namespace tessera::test {

TrimSet trimSampleSet();
// `perPiece` rectangles on every piece: quad-tree cells (levels 0..12, dyadic, so that sides
// meet segments exactly) and rectangles with random fp32 corners, fixed seed.
std::vector<gpu::TrimQuery> trimSampleQueries(const TrimSet& set, size_t perPiece, uint32_t seed);
// `count` faces of one segment each (a two-point loop, there and back), nearly parallel to a
// side of a dyadic node of a piece far from the origin, at a random distance in [−2m, 2m]
// from it (negative: inside the node), m the face's margin: where fp32 rounding matters.
// Query k is face k's node.
struct NearSideSamples {
  TrimSet set;
  std::vector<gpu::TrimQuery> queries;
};
NearSideSamples nearSideTrimSamples(uint32_t count, uint32_t seed);
// A closed polygon of `count` points on the circle (centre, radius), counter-clockwise unless
// `clockwise` (a hole).
std::vector<glm::dvec2> circleLoop(glm::dvec2 centre, double radius, int count, bool clockwise);
// Even-odd point-in-loops in double (points on a segment are not asked about).
bool insideLoops(const std::vector<std::vector<glm::dvec2>>& loops, glm::dvec2 p);

}  // namespace tessera::test
