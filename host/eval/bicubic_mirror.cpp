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

float bicubicVertexTolerance(const gpu::BicubicPatch& patch, float eps) {
  return glsl::bicubicTolerance(patch, eps);
}

gpu::VertexSample bicubicVertex(const gpu::BicubicPatch& patch, float u, float v, float tol) {
  return glsl::bicubicVertex(patch, u, v, tol);
}

}  // namespace tessera::mirror
