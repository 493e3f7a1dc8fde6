#include "mesh/mesh_cleanup.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "common/first_occurrence.h"

namespace tessera {

namespace {

using CornerKey = std::array<uint32_t, 3>;  // three vertex indices, or a position's bits

struct CornerKeyHash {
  size_t operator()(const CornerKey& k) const {
    return size_t(k[0] * 0x9E3779B97F4A7C15ull ^ k[1] * 0xC2B2AE3D27D4EB4Full ^
                  k[2] * 0x165667B19E3779F9ull);
  }
};

}  // namespace

std::vector<uint32_t> weldIdenticalPositions(const std::vector<glm::vec3>& positions,
                                             unsigned threads) {
  const auto forEachKey = [&](auto&& visit) {
    for (size_t i = 0; i < positions.size(); ++i) {
      CornerKey key;
      for (int c = 0; c < 3; ++c) {
        float x = positions[i][c] == 0.0f ? 0.0f : positions[i][c];
        std::memcpy(&key[c], &x, sizeof x);
      }
      visit(i, key);
    }
  };
  return firstOccurrences<CornerKey, CornerKeyHash>(positions.size(), positions.size(),
                                                    forEachKey, threads);
}

void requireFiniteSamples(const ParamMesh& param, const std::vector<gpu::VertexSample>& samples) {
  requireFiniteSamples(param, samples.data(), samples.size());
}

void requireFiniteSamples(const ParamMesh& param, const gpu::VertexSample* samples, size_t count) {
  const auto finite = [](const gpu::vec4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  };
  for (size_t i = 0; i < count; ++i) {
    if (finite(samples[i].position) && finite(samples[i].normal)) continue;
    const ParamVertex& v = param.vertices[i];
    char where[64];
    std::snprintf(where, sizeof where, "(u, v) = (%.9g, %.9g)", double(v.u), double(v.v));
    throw std::invalid_argument(
        "patch " + std::to_string(v.patchIndex) + ": the fp32 evaluation at " + where +
        " gives a " + (finite(samples[i].position) ? "normal" : "position") +
        " that is not finite (a rational patch whose weights differ by more than fp32 can "
        "hold?)");
  }
}

}  // namespace tessera
