// Fast path for bicubic patches (the teapot's kind): fixed sizes, no allocation, no loops over
// a run-time degree. Same results as patchDerivatives (host/geometry/bezier.h) up to rounding; the
// control-point order is that of docs/conventions.md (b_ij at cp[4i + j], i along u).
#pragma once
#include <array>

#include "geometry/patch.h"

namespace tessera {

using BicubicNet = std::array<glm::dvec3, 16>;

SurfaceDerivatives bicubicDerivatives(const BicubicNet& cp, double u, double v);
// Throws std::invalid_argument unless the patch is degree (3, 3) with 16 control points.
SurfaceDerivatives bicubicDerivatives(const BezierPatch& patch, double u, double v);

}  // namespace tessera
