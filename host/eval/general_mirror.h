// The fp32 mirrors of shaders/eval_general.comp.glsl and quadtree_general.comp.glsl: the same
// source text (shaders/lib/general_eval.h, general_vertex.h, quadtree_classify.h) compiled as
// C++ with
// -ffp-contract=off, so on lavapipe they agree with the shaders bit for bit.
// `points` is the homogeneous control-point buffer the patch's firstPoint indexes.
#pragma once
#include "shaders/layout.h"

namespace tessera::mirror {

gpu::EvalSample evalGeneralSample(const gpu::GeneralPatch& patch, const gpu::vec4* points,
                                  float u, float v, float eps);

// evalGeneralSample's position and normal, bit for bit, for less work (the mesh's vertices):
// `tol` is generalVertexTolerance(patch, points, eps), one patch's for all its vertices.
float generalVertexTolerance(const gpu::GeneralPatch& patch, const gpu::vec4* points, float eps);
gpu::VertexSample evalGeneralVertex(const gpu::GeneralPatch& patch, const gpu::vec4* points,
                                    float u, float v, float tol);

// Rule T on a patch of a degree pair with a variant of its own (eval/detail/
// general_tolerance_variants.h) goes to that variant; everything else to the generic text.
gpu::NodeDecision classifyGeneralNode(const gpu::GeneralPatch& patch, const gpu::vec4* points,
                                      const gpu::QuadNode& node, uint32_t rule, int samples,
                                      const gpu::ClassifyPush& params);
// The generic text alone, whatever the degrees: what the variants must equal bit for bit.
gpu::NodeDecision classifyGeneralNodeGeneric(const gpu::GeneralPatch& patch,
                                             const gpu::vec4* points, const gpu::QuadNode& node,
                                             uint32_t rule, int samples,
                                             const gpu::ClassifyPush& params);

}  // namespace tessera::mirror
