#include "mesh/mesh_cleanup.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "common/hash_map.h"

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

std::vector<uint32_t> weldIdenticalPositions(const std::vector<glm::vec3>& positions) {
  HashMap<CornerKey, uint32_t, CornerKeyHash> first;
  first.reserve(positions.size());
  std::vector<uint32_t> remap(positions.size());
  for (uint32_t i = 0; i < positions.size(); ++i) {
    CornerKey key;
    for (int c = 0; c < 3; ++c) {
      float x = positions[i][c] == 0.0f ? 0.0f : positions[i][c];
      std::memcpy(&key[c], &x, sizeof x);
    }
    remap[i] = first.try_emplace(key, i).first->second;
  }
  return remap;
}

std::vector<bool> backToBackPairs(const std::vector<uint32_t>& indices) {
  // Key: the corners rotated to start at the smallest; its reverse has the other two swapped.
  const auto keyOf = [&](size_t t, bool reversed) {
    const uint32_t* c = &indices[3 * t];
    const size_t second = reversed ? 2 : 1, third = reversed ? 1 : 2;
    const CornerKey k = {c[0], c[second], c[third]};
    const size_t smallest = k[1] < k[0] ? (k[2] < k[1] ? 2 : 1) : (k[2] < k[0] ? 2 : 0);
    return CornerKey{k[smallest], k[(smallest + 1) % 3], k[(smallest + 2) % 3]};
  };
  const size_t count = indices.size() / 3;
  std::vector<CornerKey> keys(count);
  for (size_t t = 0; t < count; ++t) keys[t] = keyOf(t, false);
  // Triangles bucketed by their smallest corner (modulo a power of two), sorted by key within
  // a bucket: a triangle and its reverse share that corner, and triangles met one after the
  // other have nearby corners, so the lookups below stay in cache where one sort of the whole
  // mesh, or a hash table of it, missed it at nearly every step.
  size_t buckets = 1;
  while (buckets < count) buckets *= 2;
  const uint32_t mask = uint32_t(buckets - 1);
  std::vector<uint32_t> start(buckets + 1, 0);
  for (const CornerKey& k : keys) ++start[(k[0] & mask) + 1];
  for (size_t b = 0; b < buckets; ++b) start[b + 1] += start[b];
  std::vector<uint32_t> byKey(count);
  {
    std::vector<uint32_t> next(start.begin(), start.end() - 1);
    for (size_t t = 0; t < count; ++t) byKey[next[keys[t][0] & mask]++] = uint32_t(t);
  }
  // Group g: the triangles with one key; its open ones are a stack threaded through `below`.
  std::vector<uint32_t> groupOf(count);
  uint32_t groups = 0;
  for (size_t b = 0; b < buckets; ++b) {
    const auto first = byKey.begin() + start[b], last = byKey.begin() + start[b + 1];
    if (last - first > 1)
      std::sort(first, last, [&](uint32_t x, uint32_t y) { return keys[x] < keys[y]; });
    for (auto i = first; i != last; ++i)
      groupOf[*i] = i != first && keys[*i] == keys[*(i - 1)] ? groupOf[*(i - 1)] : groups++;
  }
  constexpr uint32_t kNone = UINT32_MAX;
  std::vector<uint32_t> top(groups, kNone), below(count, kNone);
  std::vector<bool> cancelled(count, false);
  for (size_t t = 0; t < count; ++t) {
    // The latest open triangle with this one's reverse key, if any, cancels with it.
    const CornerKey reverse = keyOf(t, true);
    const uint32_t b = reverse[0] & mask;
    const auto last = byKey.begin() + start[b + 1];
    const auto found = std::lower_bound(byKey.begin() + start[b], last, reverse,
                                        [&](uint32_t x, const CornerKey& k) { return keys[x] < k; });
    if (found != last && keys[*found] == reverse) {
      uint32_t& open = top[groupOf[*found]];
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
