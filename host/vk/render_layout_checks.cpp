// Pins the rendering structs of shaders/layout.h (the push constants of mesh.*.glsl) on the
// host side, as host/vk/layout_checks.cpp does for the compute structs.
#include <cstddef>

#include "shaders/layout.h"

namespace tessera::gpu {

static_assert(sizeof(MeshDrawPush) == 112, "MeshDrawPush: 6 vec4 + 4 scalars");
static_assert(sizeof(MeshDrawPush) <= 128, "MeshDrawPush: within the guaranteed push range");
static_assert(offsetof(MeshDrawPush, eye) == 64 && offsetof(MeshDrawPush, light) == 80 &&
                  offsetof(MeshDrawPush, colourMode) == 96 &&
                  offsetof(MeshDrawPush, wireframe) == 100 &&
                  offsetof(MeshDrawPush, wireWidth) == 104,
              "MeshDrawPush member offsets");
// The peer's captured triangle (std430: vec4s at 16-byte steps, then a vec2 and two uints).
static_assert(sizeof(TessPeerTriangle) == 80 && offsetof(TessPeerTriangle, uv01) == 48 &&
                  offsetof(TessPeerTriangle, uv2) == 64 &&
                  offsetof(TessPeerTriangle, patchIndex) == 72,
              "TessPeerTriangle layout");

}  // namespace tessera::gpu
