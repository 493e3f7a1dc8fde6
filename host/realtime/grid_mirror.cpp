#include "realtime/detail/grid_mirror.h"

#include "common/glsl_builtins.h"

namespace tessera::mirror {
namespace glsl {
namespace {  // each mirror translation unit gets its own copy of the shared functions
// grid_eval.h needs bicubic_eval.h's helpers but not its whole-sample entry point, which this
// translation unit therefore leaves unused: expected, not a warning.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include "shaders/lib/shared_glsl_cpp.h"
#include "shaders/lib/bicubic_eval.h"
#include "shaders/lib/grid_eval.h"
#pragma GCC diagnostic pop
}  // namespace
}  // namespace glsl

void evalGridRow(const gpu::BicubicPatch& patch, uint32_t row, uint32_t pointsPerSide, float eps,
                 gpu::GridVertex* out) {
  // The shader's main(), line for line.
  float scale = glsl::bicubicScale(patch);
  float tol = eps * scale * scale;
  float u = glsl::gridParam(row, pointsPerSide);
  glsl::GridRow r = glsl::gridRow(patch, u);
  for (uint32_t j = 0; j < pointsPerSide; ++j)
    out[j] = glsl::gridVertex(patch, r, u, glsl::gridParam(j, pointsPerSide), tol);
}

}  // namespace tessera::mirror
