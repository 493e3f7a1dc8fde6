// From a scene (io/scene_reader.h) to what the tessellator takes today: bicubic Bézier
// patches. B-spline surfaces become their Bézier pieces (bspline_to_bezier.h); polynomial
// patches below degree 3 are degree-elevated exactly (degree_elevation.h). Rational patches
// whose weights are all equal are polynomial and are converted exactly; other rational
// patches and degrees above 3 are rejected: a documented limitation (docs/scene_format.md).
#pragma once
#include <vector>

#include "io/scene_reader.h"
#include "patch.h"

namespace tessera {

// The bicubic patches of `scene`, surfaces in file order (Scene::order; bezier, rational,
// bsplines for a scene built in code), a B-spline's pieces u-major as bezierPatches() gives
// them. Throws InputError naming scene.source and the surface's line: kind Degree for a
// degree above 3 ("... (degree 5×4 at surface 3)"), kind Weight for a rational patch with
// unequal weights. Control nets of the wrong size throw std::invalid_argument (a bug in the
// code that built the scene; the reader never produces them).
std::vector<BezierPatch> sceneToBicubicPatches(const Scene& scene);

}  // namespace tessera
