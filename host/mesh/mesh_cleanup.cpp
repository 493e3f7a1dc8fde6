#include "mesh/mesh_cleanup.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace tessera {

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
