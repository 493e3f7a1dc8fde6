// The CPU classification of (u, v) triangles against a face's trimming loops, for the trimmed
// mesher (mesher.h). A triangle that no trim segment comes within `margin` of lies wholly on
// one side of every loop, so one point decides it (the nonzero winding rule with the loops'
// orientation: material to the left). Anything nearer is Crossing: the mesher drops it and
// fills the gap, so a triangle wrongly called Crossing costs only a re-triangulation, never a
// hole or an overlap. The GPU classifier of quad-tree nodes (issue 17's trimgpu part) decides
// the same three cases for rectangles; classifyTrimTriangle is kept small so the two can share
// their text later.
#pragma once
#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "trim/trimmed_face.h"

namespace tessera {

enum class TrimClass { Inside, Outside, Crossing };

struct TrimSegment {
  glm::dvec2 a, b;
};

// The segments of all loops of one face, binned in a uniform grid over their bounding box so
// that a query looks only at the segments near it.
class TrimSegmentIndex {
 public:
  explicit TrimSegmentIndex(const std::vector<TrimLoop>& loops);
  // Segments whose bounding box meets [lo, hi] (each at most once, unordered).
  void near(glm::dvec2 lo, glm::dvec2 hi, std::vector<uint32_t>& out) const;
  const std::vector<TrimSegment>& segments() const { return segments_; }
  // trimWindingNumber(segments(), p), from the segments binned in p's row of cells at or
  // right of p's cell: the others count 0 in Sunday's rule (their v-range misses p, or they
  // end left of p: then the rounded side test cannot have the counting sign either).
  int windingNumber(glm::dvec2 p) const;
  glm::dvec2 lo() const { return lo_; }
  glm::dvec2 hi() const { return hi_; }

 private:
  std::vector<TrimSegment> segments_;
  glm::dvec2 lo_{0}, hi_{0}, cell_{1};
  int cellsU_ = 1, cellsV_ = 1;
  std::vector<uint32_t> binStart_;  // cell c's segments: binned_[binStart_[c], binStart_[c + 1])
  std::vector<uint32_t> binned_;
  struct Bin {
    const uint32_t *first, *last;
    const uint32_t* begin() const { return first; }
    const uint32_t* end() const { return last; }
  };
  Bin bin(size_t c) const { return {binned_.data() + binStart_[c], binned_.data() + binStart_[c + 1]}; }
  mutable std::vector<uint32_t> stamp_;
  mutable uint32_t query_ = 0;
};

// The winding number of the loops around `p` (outer loops counter-clockwise count +1, holes
// −1); p is in the material where it is > 0. p must not lie on a loop.
int trimWindingNumber(const std::vector<TrimSegment>& segments, glm::dvec2 p);

// Distance between two closed segments in the plane.
double segmentDistance(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 q0, glm::dvec2 q1);
// segmentDistance(p0, p1, q0, q1) > distance, the same answer, without the four point-segment
// distances when the segments' boxes lie apart by more than `distance` and the rounding.
bool segmentsFartherThan(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 q0, glm::dvec2 q1,
                         double distance);

// Crossing when a segment lies within `margin` of the closed triangle (it meets an edge, or
// lies inside it: a small hole loop in one triangle is Crossing too); otherwise Inside or
// Outside by the winding number at the centroid.
TrimClass classifyTrimTriangle(const std::array<glm::dvec2, 3>& triangle,
                               const TrimSegmentIndex& index, double margin);

}  // namespace tessera
