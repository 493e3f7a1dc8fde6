#include "eval/general_mirror.h"

#include "common/glsl_builtins.h"

namespace tessera::mirror {
namespace glsl {
namespace {  // each mirror translation unit gets its own copy of the shared functions
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"  // the bicubic entry points are unused here
#include "shaders/lib/shared_glsl_cpp.h"
#include "shaders/lib/bicubic_eval.h"
using glm::ceil;
#include "shaders/lib/division_count.h"  // gNet: thread_local, so outside the kernel struct
#include "shaders/lib/tolerance_bound.h"
#include "shaders/lib/tolerance_net.h"

// The shaders' control-point buffer as a member of the same name, so that the shared text
// reads it unchanged (as stencil_mirror.cpp does).
struct GeneralKernel {
  const vec4* controlPoints;
#include "shaders/lib/general_eval.h"
#include "shaders/lib/tolerance_general.h"
#define CLASSIFY_PATCH GeneralPatch
#define CLASSIFY_EVAL evalGeneral
#define CLASSIFY_SCALE generalScale
#define CLASSIFY_SECOND_BOUNDS generalSecondBounds
#include "shaders/lib/quadtree_classify.h"
};
#pragma GCC diagnostic pop
}  // namespace
}  // namespace glsl

gpu::EvalSample evalGeneralSample(const gpu::GeneralPatch& patch, const gpu::vec4* points,
                                  float u, float v, float eps) {
  return glsl::GeneralKernel{points}.evalGeneralSample(patch, u, v, eps);
}

gpu::NodeDecision classifyGeneralNode(const gpu::GeneralPatch& patch, const gpu::vec4* points,
                                      const gpu::QuadNode& node, uint32_t rule, int samples,
                                      const gpu::ClassifyPush& params) {
  return glsl::GeneralKernel{points}.classifyNode(patch, node, rule, samples, params);
}

}  // namespace tessera::mirror
