// The fp32 mirror of shaders/quadtree.comp.glsl (same source text, shaders/lib/
// quadtree_classify.h, compiled as C++): bit-identical decisions on lavapipe.
#pragma once
#include "shaders/layout.h"

namespace tessera::mirror {

gpu::NodeDecision classifyNode(const gpu::BicubicPatch& patch, const gpu::QuadNode& node,
                               uint32_t rule, int samples, const gpu::ClassifyPush& params);

// Rule T's decision (lib/tolerance_bound.h, toleranceDecision) from a node's bound terms
// (M_ss, M_st, M_tt, guard) found elsewhere: the bound (M_ss + 2·M_st + M_tt)/8 with the
// relative guard, leaf within δ, else the grid or midpoint split the shader would choose.
gpu::NodeDecision toleranceDecisionOf(gpu::vec4 bounds, const gpu::QuadNode& node,
                                      const gpu::ClassifyPush& params);

}  // namespace tessera::mirror
