#include "loop/detail/stencil_mirror.h"

#include "common/glsl_builtins.h"

namespace tessera::mirror {
namespace glsl {
namespace {

#include "shaders/lib/shared_glsl_cpp.h"

// The shader's storage buffers, as members of the same names, so that the shared text reads
// them unchanged.
struct StencilKernel {
  const uint* offsets;
  const uint* indices;
  const float* weights;
  float* values;
#include "shaders/lib/stencil_apply.h"
};

}  // namespace
}  // namespace glsl

void applyStencils(const uint32_t* offsets, const uint32_t* indices, const float* weights,
                   float* values, uint32_t first, uint32_t count, uint32_t sourceRows,
                   uint32_t width) {
  glsl::StencilKernel kernel{offsets, indices, weights, values};
  for (uint32_t i = 0; i < count; ++i) kernel.applyStencil(first + i, sourceRows, width);
}

}  // namespace tessera::mirror
