// Rule T's fp32 mirror for general patches once more per degree pair, as the Vulkan side builds
// quadtree_general_tolerance_<kind><n>x<m>.comp (shaders/CMakeLists.txt): the same shared text
// (lib/tolerance_general.h, tolerance_net.h, division_count.h) compiled with the degrees as
// constants (DIVISION_FIXED_DEGREE_U/V, DIVISION_FIXED_POLYNOMIAL/RATIONAL), one translation
// unit a pair (host/eval/general_tolerance_<kind><n>x<m>.cpp, each including
// general_tolerance_variant.inc). Constant trip counts let the compiler unroll the loops over
// the net; the arithmetic and its order are the generic mirror's, so the decisions are equal
// bit for bit (tests/test_tolerance_variants.cpp).
#pragma once
#include <cstdint>

#include "shaders/layout.h"

namespace tessera::mirror {

// Rule T's decision for one node of `patch` (whose degrees and kind must be the variant's).
using GeneralToleranceClassify = gpu::NodeDecision (*)(const gpu::GeneralPatch& patch,
                                                       const gpu::vec4* points,
                                                       const gpu::QuadNode& node,
                                                       const gpu::ClassifyPush& params);

// The Vulkan side's pairs (shaders/CMakeLists.txt, TESSERA_GENERAL_TOLERANCE_VARIANTS): polynomial
// up to 3 × 3, rational conic × line, conic × conic and 3 × 3 (rule T's patches in pixels). One
// list, X(kind, rational, n, m) a pair, for the declarations below, generalToleranceVariant's
// dispatch and the mirror's fixed-degree vertex path (general_mirror.cpp), so that they cannot
// drift apart.
#define TESSERA_GENERAL_DEGREE_PAIRS(X) \
  X(p, 0, 1, 1)                         \
  X(p, 0, 1, 2)                         \
  X(p, 0, 1, 3)                         \
  X(p, 0, 2, 1)                         \
  X(p, 0, 2, 2)                         \
  X(p, 0, 2, 3)                         \
  X(p, 0, 3, 1)                         \
  X(p, 0, 3, 2)                         \
  X(p, 0, 3, 3)                         \
  X(r, 1, 2, 1)                         \
  X(r, 1, 1, 2)                         \
  X(r, 1, 2, 2)                         \
  X(r, 1, 3, 3)

// A degree pair and kind as one number, the dispatchers' switch key; degrees past 7 (no general
// patch has them) take a key no pair has.
constexpr uint32_t generalDegreePairKey(bool rational, uint32_t n, uint32_t m) {
  return n <= 7 && m <= 7 ? (rational ? 64u : 0u) + n * 8u + m : UINT32_MAX;
}

#define TESSERA_DECLARE_GENERAL_TOLERANCE_VARIANT(kind, rational, n, m)                   \
  gpu::NodeDecision generalTolerance_##kind##n##x##m(                                    \
      const gpu::GeneralPatch& patch, const gpu::vec4* points, const gpu::QuadNode& node, \
      const gpu::ClassifyPush& params);
TESSERA_GENERAL_DEGREE_PAIRS(TESSERA_DECLARE_GENERAL_TOLERANCE_VARIANT)
#undef TESSERA_DECLARE_GENERAL_TOLERANCE_VARIANT

// The variant for the patch's degree pair and kind, or null where only the generic mirror
// (general_mirror.h, classifyGeneralNode) classifies it.
GeneralToleranceClassify generalToleranceVariant(const gpu::GeneralPatch& patch);

}  // namespace tessera::mirror
