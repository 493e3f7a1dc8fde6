// The fp32 mirror of shaders/division_count.comp.glsl: the same source text
// (shaders/lib/division_count.h) compiled as C++ with -ffp-contract=off, so on lavapipe it must
// agree with the shader bit for bit.
#pragma once
#include "shaders/layout.h"

namespace tessera::mirror {

// `points` holds (degreeU + 1)·(degreeV + 1) homogeneous control points.
gpu::DivisionResult divisionCounts(const gpu::DivisionPatch& patch, const gpu::vec4* points,
                                   const gpu::DivisionPush& params);

}  // namespace tessera::mirror
