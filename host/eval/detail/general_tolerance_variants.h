// Rule T's fp32 mirror for general patches once more per degree pair, as the Vulkan side builds
// quadtree_general_tolerance_<kind><n>x<m>.comp (shaders/CMakeLists.txt): the same shared text
// (lib/tolerance_general.h, tolerance_net.h, division_count.h) compiled with the degrees as
// constants (DIVISION_FIXED_DEGREE_U/V, DIVISION_FIXED_POLYNOMIAL/RATIONAL), one translation
// unit a pair (host/eval/general_tolerance_<kind><n>x<m>.cpp, each including
// general_tolerance_variant.inc). Constant trip counts let the compiler unroll the loops over
// the net; the arithmetic and its order are the generic mirror's, so the decisions are equal
// bit for bit (tests/test_tolerance_variants.cpp).
#pragma once
#include "shaders/layout.h"

namespace tessera::mirror {

// Rule T's decision for one node of `patch` (whose degrees and kind must be the variant's).
using GeneralToleranceClassify = gpu::NodeDecision (*)(const gpu::GeneralPatch& patch,
                                                       const gpu::vec4* points,
                                                       const gpu::QuadNode& node,
                                                       const gpu::ClassifyPush& params);

#define TESSERA_GENERAL_TOLERANCE_VARIANT(kind, n, m)                                     \
  gpu::NodeDecision generalTolerance_##kind##n##x##m(                                    \
      const gpu::GeneralPatch& patch, const gpu::vec4* points, const gpu::QuadNode& node, \
      const gpu::ClassifyPush& params);
// The Vulkan side's pairs: polynomial up to 3 × 3, rational conic × line and conic × conic.
TESSERA_GENERAL_TOLERANCE_VARIANT(p, 1, 1)
TESSERA_GENERAL_TOLERANCE_VARIANT(p, 1, 2)
TESSERA_GENERAL_TOLERANCE_VARIANT(p, 1, 3)
TESSERA_GENERAL_TOLERANCE_VARIANT(p, 2, 1)
TESSERA_GENERAL_TOLERANCE_VARIANT(p, 2, 2)
TESSERA_GENERAL_TOLERANCE_VARIANT(p, 2, 3)
TESSERA_GENERAL_TOLERANCE_VARIANT(p, 3, 1)
TESSERA_GENERAL_TOLERANCE_VARIANT(p, 3, 2)
TESSERA_GENERAL_TOLERANCE_VARIANT(p, 3, 3)
TESSERA_GENERAL_TOLERANCE_VARIANT(r, 2, 1)
TESSERA_GENERAL_TOLERANCE_VARIANT(r, 1, 2)
TESSERA_GENERAL_TOLERANCE_VARIANT(r, 2, 2)
#undef TESSERA_GENERAL_TOLERANCE_VARIANT

// The variant for the patch's degree pair and kind, or null where only the generic mirror
// (general_mirror.h, classifyGeneralNode) classifies it.
GeneralToleranceClassify generalToleranceVariant(const gpu::GeneralPatch& patch);

}  // namespace tessera::mirror
