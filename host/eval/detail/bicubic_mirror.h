// The fp32 mirror of shaders/eval.comp.glsl and eval_vertices.comp.glsl: the same source text (shaders/lib/bicubic_eval.h)
// compiled as C++ with -ffp-contract=off, so on a device that does not fuse multiply-adds
// (lavapipe) it must agree with the shader bit for bit.
#pragma once
#include "shaders/layout.h"

namespace tessera::mirror {

gpu::EvalSample evalBicubicSample(const gpu::BicubicPatch& patch, float u, float v, float eps);
// The mirror of shaders/eval_vertices.comp.glsl: evalBicubicSample's position and normal.
gpu::VertexSample evalBicubicVertex(const gpu::BicubicPatch& patch, float u, float v, float eps);

}  // namespace tessera::mirror
