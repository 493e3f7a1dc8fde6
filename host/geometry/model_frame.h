// The local frame a tessellation works in (issue 18, "The same answer at any scale and
// position"): the quad-tree, the fp32 classifiers and evaluators (GPU and mirror) and the
// welding of equal positions all see the model's control points as (P − centre)/scale, every
// coordinate in [−1, 1] whatever the model's units or position; the mesh's positions go back to
// model coordinates once, in double, when it is handed out (docs/quadtree.md, "The local
// frame"). One frame per model, the same for every patch: shared sides stay bit-identical.
#pragma once
#include <glm/glm.hpp>
#include <vector>

#include "geometry/patch.h"

namespace tessera {

// The axis-aligned bounding box of every control point of every patch, points of weight 0
// left out (a direction, not a position: scenes keep them as the origin). empty when there
// is no point.
struct ControlPointBox {
  glm::dvec3 lo{0.0}, hi{0.0};
  bool empty = true;
};
ControlPointBox controlPointBox(const std::vector<BezierPatch>& patches);
// `box` grown by one patch's points: a caller whose patches sit inside other records walks
// them without copying each into one vector.
void extendBox(ControlPointBox& box, const BezierPatch& patch);

// model = local·scale + centre. centre: the box's midpoint; scale: its largest half-extent
// (1 for a box of one point). Both scale exactly with the model, so the teapot at 10⁻³⁰ or
// 10³⁰ has the same local control points as at 10⁰ (each rounded once in double, then to fp32);
// a power of two would round the scaled model's local points differently (by the factor
// between the scale and its power of two), and rules C and D follow rounding: their split
// points move. Computed from halves and differences, no squares, so 10^±300 neither over- nor
// underflows.
struct ModelFrame {
  glm::dvec3 centre{0.0};
  double scale = 1.0;

  glm::dvec3 toLocal(const glm::dvec3& model) const { return (model - centre) / scale; }
  glm::dvec3 toModel(const glm::dvec3& local) const { return local * scale + centre; }
};

ModelFrame modelFrame(const std::vector<BezierPatch>& patches);
ModelFrame modelFrame(const ControlPointBox& box);  // the same frame from the patches' box

// The patches' control points in `frame`, weights unchanged (a rational patch's affine points
// move; w·(P − c)/s is its homogeneous form there). A point of weight 0 becomes the local
// origin (it has no position; the homogeneous form is 0 either way).
std::vector<BezierPatch> toLocalFrame(std::vector<BezierPatch> patches, const ModelFrame& frame);

}  // namespace tessera
