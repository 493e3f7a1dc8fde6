// How far a real-time frame read back from the GPU is from another copy of it (the frame of
// tessellate(), or the fp32 mirror's): entries that differ, and the largest position difference.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "shaders/layout.h"

namespace tessera::test {

// Off lavapipe the GPU fuses multiply-adds the mirror keeps apart; a stitched frame's positions
// then move by a few fp32 ulps (largest 3.8e-6 on an H100, coordinates up to 12) and its
// indices, laid out on the host, do not move at all.
constexpr double kFusedPositionBand = 1e-5;

struct FrameDifference {
  size_t vertices = 0, indices = 0;
  double largest = 0;  // largest coordinate difference of a position
};

inline FrameDifference frameDifference(const gpu::GridVertex* vertices, const uint32_t* indices,
                                       const gpu::GridVertex* expectedVertices,
                                       const uint32_t* expectedIndices, size_t vertexCount,
                                       size_t indexCount) {
  FrameDifference d;
  for (size_t v = 0; v < vertexCount; ++v)
    if (std::memcmp(&vertices[v], &expectedVertices[v], sizeof(gpu::GridVertex)) != 0) {
      ++d.vertices;
      for (int c = 0; c < 3; ++c)
        d.largest = std::max(d.largest, std::abs(double(vertices[v].position[c]) -
                                                 double(expectedVertices[v].position[c])));
    }
  for (size_t k = 0; k < indexCount; ++k) d.indices += indices[k] != expectedIndices[k];
  return d;
}

}  // namespace tessera::test
