// Every B-rep edge discretised once (docs/cad.md, "Edges"): parameters along the edge and the
// shared points they become. Faces map the same parameters through their own pcurves, so the
// two faces of an edge take the very same 3D points: the mesh is watertight across faces.
#pragma once
#include <TopTools_IndexedMapOfShape.hxx>
#include <atomic>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace tessera {

struct EdgeSamples {
  std::vector<double> params;  // increasing, first and last the edge's range
  // The shared points of the parameters: the ends are the vertices' points (firstId, lastId),
  // the interior ones consecutive from firstInteriorId (shareInteriorSamples numbers them), all
  // firstId on a degenerated edge. Kept as three numbers, not a vector per edge (an allocation).
  uint32_t firstId = 0, lastId = 0, firstInteriorId = 0;
  // The edge's 3D curve at each parameter (its ends within the vertices' tolerance of their
  // points); empty for a degenerated edge. A plane's pcurve, where the file stores none, is the
  // projection of these (BRep_Tool::CurveOnPlane), which the import takes directly.
  std::vector<glm::dvec3> curvePoints;
  bool degenerated = false;        // a pole: every id is the vertex's
  double maxChordDeviation = 0.0;  // exact for circles, measured otherwise (discretiseEdge)
  double tolerance = 0.0;          // the edge's OCCT tolerance, its interior points' tolerance

  // The shared point of parameter k.
  uint32_t pointId(size_t k) const {
    if (degenerated || k == 0) return firstId;
    if (k + 1 == params.size()) return lastId;
    return firstInteriorId + static_cast<uint32_t>(k - 1);
  }
};

struct SharedPoints {
  std::vector<glm::dvec3> positions;
  std::vector<double> tolerances;  // the vertex's or edge's OCCT tolerance
};

// The memory bound of a model's edge samples (docs/hardening.md): every edge's samples counted
// into one total, checked against the memory budget (common/memory_budget.h) before a circle
// makes its samples and every few thousand samples of a bisection, so that a tolerance far
// below the model's size stops with MemoryLimitError (CLI exit 4) within a second instead of
// filling memory (CAP_50SGV_8_10.stp at δ = 10⁻¹⁴ took 2 GiB in 8 s and went on). Shared by
// the threads that discretise the edges; which edge crosses the budget first may differ, the
// error does not.
class EdgeSampleBudget {
 public:
  explicit EdgeSampleBudget(double delta) : delta_(delta) {}
  // Counts `samples` more; throws MemoryLimitError once the total's estimate passes the budget.
  void add(double samples);
  // The bytes a sample is counted as: its parameter and 3D point (32), its shared point (32),
  // two faces' loop entries (2 × 20) and trim segments (2 × 16), the mesh vertex it becomes (56).
  static constexpr uint64_t kBytesPerSample = 192;

 private:
  std::atomic<uint64_t> samples_{0};
  double delta_;
};

// The rule: a straight edge is one segment; a circle the fewest equal segments (at least 4)
// whose sagitta is within delta, exactly (proven); any other curve starts as 4 segments (a
// closed edge then bounds an area) and a segment [a, b] is halved while the curve, sampled at
// 15 interior parameters, lies farther than delta from the chord: measured, not proven, a
// wiggle between samples of a segment can escape it (docs/cad.md). A degenerated edge (a
// point in 3D, a segment in uv) gets 8 segments, all at its vertex's point.
// The edge is taken FORWARD. The vertex with index k in `vertices` is shared point k − 1 (the
// vertices come first in SharedPoints). The interior samples' ids are left to
// shareInteriorSamples: reading the shape only, discretiseEdge may run for several edges at once.
// A bisection stops where the measured deviation is within the points' own rounding (a few
// ulps of their coordinates): below it no split can tell the curve from its chord. `budget`
// (null: none) counts the samples.
EdgeSamples discretiseEdge(const TopoDS_Shape& edge, double delta,
                           const TopTools_IndexedMapOfShape& vertices,
                           EdgeSampleBudget* budget = nullptr);
// The same with the vertices' shared points already known (`firstId` the FORWARD-taken edge's
// first vertex's, `lastId` its last's), as the import's map of the shape finds them.
EdgeSamples discretiseEdge(const TopoDS_Shape& edge, double delta, uint32_t firstId,
                           uint32_t lastId, EdgeSampleBudget* budget = nullptr);

// Appends the edge's interior samples to `points` and gives them their ids: called edge by edge
// in the edges' order, so the numbering is the same whatever the threads that discretised them.
void shareInteriorSamples(EdgeSamples& samples, SharedPoints& points);

}  // namespace tessera
