// The fp32 mirror of shaders/reduction_apply.comp.glsl: the same source text
// (shaders/lib/band_apply.h) compiled as C++ with -ffp-contract=off, so on a device that does
// not fuse multiply-adds (lavapipe) it agrees with the shader bit for bit.
#pragma once
#include <cstdint>
#include <glm/glm.hpp>

namespace tessera::mirror {

// results[c·rows + i] for every curve c < curves and row i < rows (see band_apply.h).
void applyBandRows(const uint32_t* firsts, const uint32_t* offsets, const float* weights,
                   const glm::vec4* points, glm::vec4* results, uint32_t rows, uint32_t cols,
                   uint32_t curves);

}  // namespace tessera::mirror
