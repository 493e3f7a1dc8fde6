#include "quadtree/detail/classify_mirror.h"

#include "common/glsl_builtins.h"

namespace tessera::mirror {
namespace glsl {
namespace {  // each mirror translation unit gets its own copy of the shared functions
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"  // the point-evaluation entry is unused here
#include "shaders/lib/shared_glsl_cpp.h"
#include "shaders/lib/bicubic_eval.h"
// toleranceDecisionOf's terms have C = 0 (the revolution bound): skip their zero norms.
#define TOLERANCE_DECISION_CENTRELESS_SHORTCUT
// The bicubic shaders' configuration (lib/tolerance_bicubic_shader.glsl): rows of order 4 and
// loops of constant trip counts with tests instead of breaks, which GCC unrolls and folds as
// spirv-opt does there. The same arithmetic in the same order: the same bits.
#define TOLERANCE_ROW_ORDER 4
#define TOLERANCE_UNROLL _Pragma("GCC unroll 4")
#include "shaders/lib/tolerance_bound.h"
#undef TOLERANCE_DECISION_CENTRELESS_SHORTCUT
#include "shaders/lib/quadtree_classify.h"
#pragma GCC diagnostic pop
}  // namespace
}  // namespace glsl

gpu::NodeDecision classifyNode(const gpu::BicubicPatch& patch, const gpu::QuadNode& node,
                               uint32_t rule, int samples, const gpu::ClassifyPush& params) {
  return glsl::classifyNode(patch, node, rule, samples, params);
}

gpu::NodeDecision toleranceDecisionOf(gpu::vec4 bounds, const gpu::QuadNode& node,
                                      const gpu::ClassifyPush& params) {
  return glsl::toleranceDecision(glsl::toleranceTermsOf(bounds), node, params);
}

}  // namespace tessera::mirror
