#include "reduction/detail/band_mirror.h"

#include "common/glsl_builtins.h"

namespace tessera::mirror {
namespace glsl {
namespace {

#include "shaders/lib/shared_glsl_cpp.h"

// The shader's storage buffers, as members of the same names, so that the shared text reads
// them unchanged.
struct BandKernel {
  const uint* firsts;
  const uint* offsets;
  const float* weights;
  const vec4* points;
  vec4* results;
#include "shaders/lib/band_apply.h"
};

}  // namespace
}  // namespace glsl

void applyBandRows(const uint32_t* firsts, const uint32_t* offsets, const float* weights,
                   const glm::vec4* points, glm::vec4* results, uint32_t rows, uint32_t cols,
                   uint32_t curves) {
  glsl::BandKernel kernel{firsts, offsets, weights, points, results};
  for (uint32_t c = 0; c < curves; ++c) {
    for (uint32_t i = 0; i < rows; ++i) kernel.applyBandRow(c, i, rows, cols);
  }
}

}  // namespace tessera::mirror
