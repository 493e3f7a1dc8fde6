#include "division/detail/count_mirror.h"

#include "common/glsl_builtins.h"

namespace tessera::mirror::glsl {
namespace {  // each mirror translation unit gets its own copy of the shared functions
using glm::ceil;
#include "shaders/lib/shared_glsl_cpp.h"
#include "shaders/lib/division_count.h"
}  // namespace
}  // namespace tessera::mirror::glsl

namespace tessera::mirror {

gpu::DivisionResult divisionCounts(const gpu::DivisionPatch& patch, const gpu::vec4* points,
                                   const gpu::DivisionPush& params) {
  glsl::gNet.n = int(patch.degreeU);
  glsl::gNet.m = int(patch.degreeV);
  const int count = (glsl::gNet.n + 1) * (glsl::gNet.m + 1);
  for (int k = 0; k < count; ++k) glsl::gNet.h[k] = points[k];
  return glsl::divisionCounts(params);
}

}  // namespace tessera::mirror
