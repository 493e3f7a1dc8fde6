// Pins the grid-evaluation structs of shaders/layout.h (grid_eval.comp.glsl) on the host side.
#include <cstddef>

#include "shaders/layout.h"

namespace tessera::gpu {

static_assert(sizeof(GridVertex) == 32, "GridVertex: the 32-byte vertex of the bandwidth cap");
static_assert(offsetof(GridVertex, normal) == 16, "GridVertex member offsets");
static_assert(sizeof(GridEvalPush) == 16, "GridEvalPush: 4 scalars");
static_assert(offsetof(GridEvalPush, pointsPerSide) == 4 &&
                  offsetof(GridEvalPush, degenerateEps) == 8,
              "GridEvalPush member offsets");

}  // namespace tessera::gpu

namespace tessera::gpu {
static_assert(sizeof(TessPeerPush) == 96, "TessPeerPush: 6 vec4");
static_assert(offsetof(TessPeerPush, params) == 64 && offsetof(TessPeerPush, rules) == 80,
              "TessPeerPush member offsets");
}  // namespace tessera::gpu
