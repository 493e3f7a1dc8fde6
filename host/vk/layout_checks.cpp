// Pins the std430 layouts of shaders/layout.h on the host side: if a struct changes size or
// a member moves, the build fails here instead of the GPU reading garbage.
#include <cstddef>

#include "shaders/layout.h"

namespace tessera::gpu {

static_assert(sizeof(vec4) == 16 && alignof(vec4) <= 16, "glm::vec4 must be 16 bytes");
static_assert(sizeof(BicubicPatch) == 256, "BicubicPatch: 16 vec4");
static_assert(sizeof(EvalQuery) == 16, "EvalQuery: 4 scalars");
static_assert(offsetof(EvalQuery, patchIndex) == 0 && offsetof(EvalQuery, u) == 4 &&
                  offsetof(EvalQuery, v) == 8,
              "EvalQuery member offsets");
static_assert(sizeof(EvalSample) == 64, "EvalSample: 4 vec4");
static_assert(offsetof(EvalSample, du) == 16 && offsetof(EvalSample, dv) == 32 &&
                  offsetof(EvalSample, normalKappa) == 48,
              "EvalSample member offsets");
static_assert(sizeof(VertexSample) == 32 && offsetof(VertexSample, normal) == 16,
              "VertexSample: 2 vec4");
static_assert(sizeof(VertexEvalPush) == 16 && offsetof(VertexEvalPush, degenerateEps) == 4,
              "VertexEvalPush: 4 scalars");
static_assert(sizeof(EvalPush) == 16, "EvalPush: 4 scalars");
static_assert(sizeof(QuadNode) == 32 && offsetof(QuadNode, patchIndex) == 16 &&
                  offsetof(QuadNode, level) == 20,
              "QuadNode layout");
static_assert(sizeof(NodeDecision) == 32 && offsetof(NodeDecision, cause) == 16 &&
                  offsetof(NodeDecision, linearity) == 20 && offsetof(NodeDecision, flatness) == 24 &&
                  offsetof(NodeDecision, pad) == 28,
              "NodeDecision layout");
static_assert(sizeof(ToleranceNetBounds) == 48 && offsetof(ToleranceNetBounds, ssCentre) == 16 &&
                  offsetof(ToleranceNetBounds, stCentre) == 32,
              "ToleranceNetBounds layout");
static_assert(sizeof(ClassifyPush) == 32 && offsetof(ClassifyPush, maxDepth) == 16 &&
                  offsetof(ClassifyPush, nodeCount) == 20 &&
                  offsetof(ClassifyPush, tolerance) == 24 &&
                  offsetof(ClassifyPush, toleranceSplitCap) == 28,
              "ClassifyPush layout");
static_assert(sizeof(GeneralPatch) == 16 && offsetof(GeneralPatch, degreeV) == 4 &&
                  offsetof(GeneralPatch, rational) == 8 && offsetof(GeneralPatch, firstPoint) == 12,
              "GeneralPatch: 4 scalars");

}  // namespace tessera::gpu
