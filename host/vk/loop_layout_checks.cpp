// Pins the std430 layout of the Loop stencil structs in shaders/layout.h (see layout_checks.cpp).
#include <cstddef>

#include "shaders/layout.h"

namespace tessera::gpu {

static_assert(sizeof(LoopStencilPush) == 16, "LoopStencilPush: 4 scalars");
static_assert(offsetof(LoopStencilPush, firstStencil) == 0 &&
                  offsetof(LoopStencilPush, stencilCount) == 4 &&
                  offsetof(LoopStencilPush, sourceRows) == 8 && offsetof(LoopStencilPush, width) == 12,
              "LoopStencilPush member offsets");

}  // namespace tessera::gpu
