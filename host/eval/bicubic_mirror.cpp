#include "eval/detail/bicubic_mirror.h"

#include "common/glsl_builtins.h"

namespace tessera::mirror {
namespace glsl {
namespace {  // each mirror translation unit gets its own copy of the shared functions
#include "shaders/lib/shared_glsl_cpp.h"
#include "shaders/lib/bicubic_eval.h"
}  // namespace
}  // namespace glsl

gpu::EvalSample evalBicubicSample(const gpu::BicubicPatch& patch, float u, float v, float eps) {
  return glsl::evalBicubicSample(patch, u, v, eps);
}

gpu::VertexSample evalBicubicVertex(const gpu::BicubicPatch& patch, float u, float v, float eps) {
  return glsl::evalBicubicVertex(patch, u, v, eps);
}

}  // namespace tessera::mirror
