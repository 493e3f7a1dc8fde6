// Pins the stitched-pattern structs of shaders/layout.h (stitch_pattern.comp.glsl) on the host.
#include <cstddef>

#include "shaders/layout.h"

namespace tessera::gpu {

static_assert(sizeof(StitchPatch) == 80, "StitchPatch: 3 uvec4 and 8 scalars");
static_assert(offsetof(StitchPatch, sideEdge) == 16 && offsetof(StitchPatch, sideFlags) == 32 &&
                  offsetof(StitchPatch, patchIndex) == 48 && offsetof(StitchPatch, firstVertex) == 60 &&
                  offsetof(StitchPatch, firstIndex) == 64,
              "StitchPatch member offsets");
static_assert(sizeof(StitchPush) == 16, "StitchPush: 4 scalars");

}  // namespace tessera::gpu
