// Pictures of a join (issue 7): three panels side by side — the two inputs apart, their
// placement, and the joined surface — each surface drawn as its Loop limit surface (refined 3
// levels, pushed to the limit), coloured by origin: first mesh, second mesh, bridge.
#pragma once
#include <cstdint>
#include <vector>

#include "loop/join.h"

namespace tessera {
namespace vk {
class Context;
}

// RGBA8, rows top to bottom, (3 · panelWidth) × height.
std::vector<uint8_t> renderJoinPicture(vk::Context& context, const LoopShape& first,
                                       const LoopShape& second, const LoopJoinResult& joined,
                                       int panelWidth, int height);

}  // namespace tessera
