// Applying one stencil of a Loop stencil table (host/loop/stencils.h) in fp32.
// Compiled twice from this one text: as GLSL in shaders/loop_stencil.comp.glsl, where
// offsets, indices, weights and values are storage buffers, and as C++ inside the struct of
// host/loop/stencil_mirror.cpp, where they are members of the same names. Every component is
// summed from 0 over the stencil's entries in table order with no fused multiply-add
// (PRECISE), so lavapipe and the mirror round identically.
// Include shared_glsl_cpp.h first.
#ifndef TESSERA_STENCIL_APPLY_H
#define TESSERA_STENCIL_APPLY_H

// Row sourceRows + s = Σ_j weights[j] · row indices[j], j = offsets[s] .. offsets[s + 1] − 1.
void applyStencil(uint s, uint sourceRows, uint width) {
  uint begin = offsets[s];
  uint end = offsets[s + 1u];
  uint target = (sourceRows + s) * width;
  for (uint c = 0u; c < width; ++c) {
    PRECISE float sum = 0.0f;
    for (uint j = begin; j < end; ++j) sum = sum + weights[j] * values[indices[j] * width + c];
    values[target + c] = sum;
  }
}

#endif
