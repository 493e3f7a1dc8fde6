// From a scene (io/scene_reader.h) to the patches the tessellator takes (tessellate.h):
// B-spline surfaces become their Bézier pieces (bspline_to_bezier.h); polynomial patches of
// degree ≤ 3 are degree-elevated to bicubic, exactly, for the bicubic fast path; higher
// degrees (≤ 7) stay as they are. Rational patches whose weights are all equal are polynomial
// and are converted exactly; other rational patches become BezierPatch with weights (the
// general path, general_patch.h). docs/scene_format.md, last section.
#pragma once
#include <vector>

#include "io/scene_reader.h"
#include "geometry/patch.h"

namespace tessera {

// The patches of `scene`, surfaces in file order (Scene::order; bezier, rational, bsplines for
// a scene built in code), a B-spline's pieces u-major as bezierPatches() gives them. A
// rational patch with a negative weight or a zero corner weight (only a scene built in code
// can have one; the reader refuses them) throws InputError kind Weight naming scene.source,
// the weights' line and the surface. Control nets of the wrong size throw
// std::invalid_argument (a bug in the code that built the scene).
std::vector<BezierPatch> sceneToPatches(const Scene& scene);

// The former name, from when scenes became bicubic patches only; kept for callers in flight.
inline std::vector<BezierPatch> sceneToBicubicPatches(const Scene& scene) {
  return sceneToPatches(scene);
}

}  // namespace tessera
