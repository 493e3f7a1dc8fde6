// Pins the std430 layout of the reduction's push constants in shaders/layout.h (see
// layout_checks.cpp).
#include <cstddef>

#include "shaders/layout.h"

namespace tessera::gpu {

static_assert(sizeof(BandApplyPush) == 16, "BandApplyPush: 4 scalars");
static_assert(offsetof(BandApplyPush, rows) == 0 && offsetof(BandApplyPush, cols) == 4 &&
                  offsetof(BandApplyPush, curves) == 8,
              "BandApplyPush member offsets");

}  // namespace tessera::gpu
