// Pins the std430 layout of the division-count structs in shaders/layout.h (see
// layout_checks.cpp).
#include <cstddef>

#include "shaders/layout.h"

namespace tessera::gpu {

static_assert(sizeof(DivisionPatch) == 16, "DivisionPatch: 4 scalars");
static_assert(offsetof(DivisionPatch, firstPoint) == 0 && offsetof(DivisionPatch, degreeU) == 4 &&
                  offsetof(DivisionPatch, degreeV) == 8,
              "DivisionPatch member offsets");
static_assert(sizeof(DivisionResult) == 32, "DivisionResult: 8 scalars");
static_assert(offsetof(DivisionResult, nu) == 0 && offsetof(DivisionResult, nv) == 4 &&
                  offsetof(DivisionResult, status) == 8 && offsetof(DivisionResult, realU) == 12 &&
                  offsetof(DivisionResult, realV) == 16 && offsetof(DivisionResult, uu) == 20 &&
                  offsetof(DivisionResult, uv) == 24 && offsetof(DivisionResult, vv) == 28,
              "DivisionResult member offsets");
static_assert(sizeof(DivisionPush) == 16, "DivisionPush: 4 scalars");
static_assert(offsetof(DivisionPush, tolerance) == 0 &&
                  offsetof(DivisionPush, maxPerDirection) == 4 &&
                  offsetof(DivisionPush, ratioPieces) == 8 && offsetof(DivisionPush, patchCount) == 12,
              "DivisionPush member offsets");

}  // namespace tessera::gpu
