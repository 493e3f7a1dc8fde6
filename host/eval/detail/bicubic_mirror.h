// The fp32 mirror of shaders/eval.comp.glsl and eval_vertices.comp.glsl: the same source text (shaders/lib/bicubic_eval.h)
// compiled as C++ with -ffp-contract=off, so on a device that does not fuse multiply-adds
// (lavapipe) it must agree with the shader bit for bit.
#pragma once
#include "shaders/layout.h"

namespace tessera::mirror {

gpu::EvalSample evalBicubicSample(const gpu::BicubicPatch& patch, float u, float v, float eps);
// The mirror of shaders/eval_vertices.comp.glsl: evalBicubicSample's position and normal.
gpu::VertexSample evalBicubicVertex(const gpu::BicubicPatch& patch, float u, float v, float eps);
// The same in two steps, so that a run of queries on one patch computes the patch's ε·L²
// (bicubicTolerance, a pass over its 16 points) once: bicubicVertex(p, u, v,
// bicubicVertexTolerance(p, eps)) is evalBicubicVertex(p, u, v, eps), bit for bit.
float bicubicVertexTolerance(const gpu::BicubicPatch& patch, float eps);
gpu::VertexSample bicubicVertex(const gpu::BicubicPatch& patch, float u, float v, float tol);

}  // namespace tessera::mirror
