// The fp32 mirror of shaders/loop_stencil.comp.glsl: the same source text
// (shaders/lib/stencil_apply.h) compiled as C++ with -ffp-contract=off, so on a device that
// does not fuse multiply-adds (lavapipe) it agrees with the shader bit for bit.
#pragma once
#include <cstdint>

namespace tessera::mirror {

// Applies stencils [first, first + count) of the table given by offsets/indices/weights to
// `values` (rows of `width` floats; stencil s writes row sourceRows + s).
void applyStencils(const uint32_t* offsets, const uint32_t* indices, const float* weights,
                   float* values, uint32_t first, uint32_t count, uint32_t sourceRows,
                   uint32_t width);

}  // namespace tessera::mirror
