#include "eval/general_mirror.h"

#include "common/glsl_builtins.h"
#include "eval/detail/general_tolerance_variants.h"

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
#include "eval/detail/general_vertex.inc"
};
#pragma GCC diagnostic pop
}  // namespace
}  // namespace glsl

gpu::EvalSample evalGeneralSample(const gpu::GeneralPatch& patch, const gpu::vec4* points,
                                  float u, float v, float eps) {
  return glsl::GeneralKernel{points}.evalGeneralSample(patch, u, v, eps);
}

float generalVertexTolerance(const gpu::GeneralPatch& patch, const gpu::vec4* points, float eps) {
  return glsl::GeneralKernel{points}.generalTolerance(patch, eps);
}

gpu::VertexSample evalGeneralVertex(const gpu::GeneralPatch& patch, const gpu::vec4* points,
                                    float u, float v, float tol) {
  return glsl::GeneralKernel{points}.generalVertex(patch, u, v, tol);
}

gpu::NodeDecision classifyGeneralNode(const gpu::GeneralPatch& patch, const gpu::vec4* points,
                                      const gpu::QuadNode& node, uint32_t rule, int samples,
                                      const gpu::ClassifyPush& params) {
  if (rule == gpu::kSplitRuleTolerance)
    if (const GeneralToleranceClassify variant = generalToleranceVariant(patch))
      return variant(patch, points, node, params);
  return classifyGeneralNodeGeneric(patch, points, node, rule, samples, params);
}

gpu::NodeDecision classifyGeneralNodeGeneric(const gpu::GeneralPatch& patch,
                                             const gpu::vec4* points, const gpu::QuadNode& node,
                                             uint32_t rule, int samples,
                                             const gpu::ClassifyPush& params) {
  return glsl::GeneralKernel{points}.classifyNode(patch, node, rule, samples, params);
}

GeneralToleranceClassify generalToleranceVariant(const gpu::GeneralPatch& patch) {
  const uint32_t n = patch.degreeU, m = patch.degreeV;
  if (patch.rational == 0u) {
    // Polynomial (n, m) up to 3 × 3, at (n − 1)·3 + m − 1.
    static constexpr GeneralToleranceClassify kPolynomial[9] = {
        generalTolerance_p1x1, generalTolerance_p1x2, generalTolerance_p1x3,
        generalTolerance_p2x1, generalTolerance_p2x2, generalTolerance_p2x3,
        generalTolerance_p3x1, generalTolerance_p3x2, generalTolerance_p3x3};
    return n >= 1 && m >= 1 && n <= 3 && m <= 3 ? kPolynomial[(n - 1) * 3 + (m - 1)] : nullptr;
  }
  if (n == 2 && m == 1) return generalTolerance_r2x1;
  if (n == 1 && m == 2) return generalTolerance_r1x2;
  if (n == 2 && m == 2) return generalTolerance_r2x2;
  return nullptr;
}

}  // namespace tessera::mirror
