// The fp32 mirrors of shaders/eval_general.comp.glsl and quadtree_general.comp.glsl: the same
// source text (shaders/lib/general_eval.h, quadtree_classify.h) compiled as C++ with
// -ffp-contract=off, so on lavapipe they agree with the shaders bit for bit.
// `points` is the homogeneous control-point buffer the patch's firstPoint indexes.
#pragma once
#include "shaders/layout.h"

namespace tessera::mirror {

gpu::EvalSample evalGeneralSample(const gpu::GeneralPatch& patch, const gpu::vec4* points,
                                  float u, float v, float eps);

gpu::NodeDecision classifyGeneralNode(const gpu::GeneralPatch& patch, const gpu::vec4* points,
                                      const gpu::QuadNode& node, uint32_t rule, int samples,
                                      const gpu::ClassifyPush& params);

}  // namespace tessera::mirror
