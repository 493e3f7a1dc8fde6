#include "mesh/mesh_cleanup.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace tessera {

std::vector<uint32_t> weldIdenticalPositions(const std::vector<glm::vec3>& positions) {
  struct Hash {
    size_t operator()(const std::array<uint32_t, 3>& k) const {
      return (size_t(k[0]) * 73856093u) ^ (size_t(k[1]) * 19349663u) ^ (size_t(k[2]) * 83492791u);
    }
  };
  std::unordered_map<std::array<uint32_t, 3>, uint32_t, Hash> first;
  std::vector<uint32_t> remap(positions.size());
  for (uint32_t i = 0; i < positions.size(); ++i) {
    std::array<uint32_t, 3> key;
    for (int c = 0; c < 3; ++c) {
      float x = positions[i][c] == 0.0f ? 0.0f : positions[i][c];
      std::memcpy(&key[c], &x, sizeof x);
    }
    remap[i] = first.emplace(key, i).first->second;
  }
  return remap;
}

std::vector<bool> backToBackPairs(const std::vector<uint32_t>& indices) {
  using Key = std::array<uint32_t, 3>;
  // Key: the corners rotated to start at the smallest; its reverse has the other two swapped.
  const auto keyOf = [&](size_t t, bool reversed) {
    Key k = {indices[3 * t], indices[3 * t + 1], indices[3 * t + 2]};
    if (reversed) std::swap(k[1], k[2]);
    std::rotate(k.begin(), std::min_element(k.begin(), k.end()), k.end());
    return k;
  };
  const size_t count = indices.size() / 3;
  // Triangles grouped by key in one sorted array (no allocation per triangle: this runs on
  // every mesh); group g's open triangles are a stack threaded through `below`.
  std::vector<std::pair<Key, uint32_t>> byKey(count);
  for (size_t t = 0; t < count; ++t) byKey[t] = {keyOf(t, false), uint32_t(t)};
  std::sort(byKey.begin(), byKey.end());
  std::vector<uint32_t> groupOf(count);
  size_t groups = 0;
  for (size_t i = 0; i < count; ++i) {
    if (i > 0 && byKey[i].first != byKey[i - 1].first) ++groups;
    groupOf[byKey[i].second] = uint32_t(groups);
  }
  constexpr uint32_t kNone = UINT32_MAX;
  std::vector<uint32_t> top(count ? groups + 1 : 0, kNone), below(count, kNone);
  std::vector<bool> cancelled(count, false);
  for (size_t t = 0; t < count; ++t) {
    // The latest open triangle with this one's reverse key, if any, cancels with it.
    const Key reverse = keyOf(t, true);
    const auto found = std::lower_bound(byKey.begin(), byKey.end(), std::make_pair(reverse, 0u));
    if (found != byKey.end() && found->first == reverse) {
      uint32_t& open = top[groupOf[found->second]];
      if (open != kNone) {
        cancelled[open] = cancelled[t] = true;
        open = below[open];
        continue;
      }
    }
    uint32_t& own = top[groupOf[t]];
    below[t] = own;
    own = uint32_t(t);
  }
  return cancelled;
}

void requireFiniteSamples(const ParamMesh& param, const std::vector<gpu::EvalSample>& samples) {
  const auto finite = [](const gpu::vec4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  };
  for (size_t i = 0; i < samples.size(); ++i) {
    if (finite(samples[i].position) && finite(samples[i].normalKappa)) continue;
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
