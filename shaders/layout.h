// Every buffer layout shared by the C++ host and the GLSL shaders (std430).
// Included by both: GLSL sees plain structs, C++ sees the same structs in tessera::gpu,
// and host/vk/layout_checks.cpp pins their sizes and offsets with static_asserts.
// Rule for std430 here: only vec4/uvec4 and 4-byte scalars, grouped in fours, so that the
// C++ and GLSL layouts cannot drift apart.
#ifndef TESSERA_SHADERS_LAYOUT_H
#define TESSERA_SHADERS_LAYOUT_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace tessera::gpu {
using uint = std::uint32_t;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
#define TESSERA_CONST(type, name, value) constexpr type name = value
#else
#define TESSERA_CONST(type, name, value) const type name = value
#endif

// Workgroup size of every 1-D compute shader.
TESSERA_CONST(uint, kLocalSize, 64u);

// A bicubic Bézier patch: control point b_ij at cp[i*4 + j], i along u, j along v.
// xyz = position, w unused (1.0).
struct BicubicPatch {
  vec4 cp[16];
};

// One evaluation request: parameter (u, v) on patch `patchIndex`.
struct EvalQuery {
  uint patchIndex;
  float u;
  float v;
  uint pad;
};

// One evaluation result. w components: position.w = 1, du.w = dv.w = 0,
// normal.w = κ (max |principal curvature|, 0 at degenerate points).
struct EvalSample {
  vec4 position;
  vec4 du;
  vec4 dv;
  vec4 normalKappa;
};

// Push constants of eval.comp.glsl.
struct EvalPush {
  uint queryCount;
  float degenerateEps;  // ε of docs/conventions.md (1e-5 in fp32)
  uint pad0;
  uint pad1;
};

#ifdef __cplusplus
}  // namespace tessera::gpu
#endif
#endif
