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
#include "shaders/lib/general_vertex.h"
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

// The pairs of rule T's variants (general_tolerance_variants.h: planes, cylinders, cones,
// spheres, tori and low-degree splines, most of a CAD model's faces) pass their degrees and kind
// as constants, so that generalVertexOfDegrees' loops unroll; the operations are those the
// patch's own degrees run.
gpu::VertexSample evalGeneralVertex(const gpu::GeneralPatch& patch, const gpu::vec4* points,
                                    float u, float v, float tol) {
  glsl::GeneralKernel kernel{points};
  switch (generalDegreePairKey(patch.rational != 0u, patch.degreeU, patch.degreeV)) {
#define TESSERA_FIXED_DEGREE_VERTEX(kind, rational, n, m) \
  case generalDegreePairKey(rational, n, m):             \
    return kernel.generalVertexOfDegrees(patch, n, m, rational, u, v, tol);
    TESSERA_GENERAL_DEGREE_PAIRS(TESSERA_FIXED_DEGREE_VERTEX)
#undef TESSERA_FIXED_DEGREE_VERTEX
    default:
      return kernel.generalVertex(patch, u, v, tol);
  }
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
  switch (generalDegreePairKey(patch.rational != 0u, patch.degreeU, patch.degreeV)) {
#define TESSERA_TOLERANCE_VARIANT_CASE(kind, rational, n, m) \
  case generalDegreePairKey(rational, n, m):                \
    return generalTolerance_##kind##n##x##m;
    TESSERA_GENERAL_DEGREE_PAIRS(TESSERA_TOLERANCE_VARIANT_CASE)
#undef TESSERA_TOLERANCE_VARIANT_CASE
    default:
      return nullptr;
  }
}

}  // namespace tessera::mirror
