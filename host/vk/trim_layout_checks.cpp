// Pins the std430 layout of the trim-classification structs in shaders/layout.h (see
// layout_checks.cpp).
#include <cstddef>

#include "shaders/layout.h"

namespace tessera::gpu {

static_assert(sizeof(TrimFace) == 48 && offsetof(TrimFace, box) == 0 &&
                  offsetof(TrimFace, firstSegment) == 16 && offsetof(TrimFace, segmentCount) == 20 &&
                  offsetof(TrimFace, margin) == 24 && offsetof(TrimFace, firstBin) == 32 &&
                  offsetof(TrimFace, binCount) == 36 && offsetof(TrimFace, binScale) == 40,
              "TrimFace layout");
static_assert(sizeof(TrimPiece) == 32 && offsetof(TrimPiece, rect) == 0 &&
                  offsetof(TrimPiece, face) == 16,
              "TrimPiece layout");
static_assert(sizeof(TrimQuery) == 32 && offsetof(TrimQuery, rect) == 0 &&
                  offsetof(TrimQuery, piece) == 16,
              "TrimQuery layout: a QuadNode's rect and patchIndex at the same offsets");
static_assert(sizeof(TrimPush) == 16 && offsetof(TrimPush, queryCount) == 0, "TrimPush layout");

}  // namespace tessera::gpu
