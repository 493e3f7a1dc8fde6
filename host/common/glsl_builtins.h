// What shaders/lib/*.h expect from GLSL, spelled for C++ (include inside a namespace after
// shaders/layout.h). Every builtin used by shared code must map to an operation that rounds
// exactly as the shader's does: dot as ((x·x + y·y) + z·z), cross as glm's (products in the
// same pairs as NIR's lowering), sqrt and division correctly rounded.
#pragma once
#include <cmath>

#include "shaders/layout.h"

namespace tessera::mirror::glsl {
using namespace tessera::gpu;
using glm::abs;
using glm::clamp;
using glm::cross;
using glm::dot;
using glm::max;
using glm::min;
using std::isnan;
using std::sqrt;
}  // namespace tessera::mirror::glsl
