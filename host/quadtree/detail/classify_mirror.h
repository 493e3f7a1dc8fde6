// The fp32 mirror of shaders/quadtree.comp.glsl (same source text, shaders/lib/
// quadtree_classify.h, compiled as C++): bit-identical decisions on lavapipe.
#pragma once
#include "shaders/layout.h"

namespace tessera::mirror {

gpu::NodeDecision classifyNode(const gpu::BicubicPatch& patch, const gpu::QuadNode& node,
                               uint32_t rule, int samples, const gpu::ClassifyPush& params);

}  // namespace tessera::mirror
