// The fp32 mirror of shaders/grid_eval.comp.glsl: the same source text (shaders/lib/grid_eval.h)
// compiled as C++ with -ffp-contract=off, bit-identical to the shader on lavapipe.
#pragma once
#include "shaders/layout.h"

namespace tessera::mirror {

// Row i of patch's P×P grid: writes P vertices to out[0 .. P−1], as one shader invocation does.
void evalGridRow(const gpu::BicubicPatch& patch, uint32_t row, uint32_t pointsPerSide, float eps,
                 gpu::GridVertex* out);

}  // namespace tessera::mirror
