#include "mesh/mesh_cleanup.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>

#include "common/first_occurrence.h"
#include "common/parallel_for.h"

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

namespace {

// Per triangle, 1 when it cancels with its reverse (backToBackPairs).
std::vector<uint8_t> cancelledFlags(const std::vector<uint32_t>& indices, unsigned threads) {
  const size_t count = indices.size() / 3;
  if (count == 0) return {};
  // Key: the corners rotated to start at the smallest; its reverse has the other two swapped.
  // Which rotation a triangle's key is (0, 1, 2) is found once, in the first pass, so the
  // bucketing and the comparisons below only read corners.
  const auto firstOf = [](uint32_t a, uint32_t b, uint32_t c) -> uint8_t {
    return b < a ? (c < b ? 2 : 1) : (c < a ? 2 : 0);
  };
  const auto keyOf = [&](size_t t, size_t first) {
    const uint32_t* c = &indices[3 * t];
    return CornerKey{c[first], c[first == 2 ? 0 : first + 1], c[first == 0 ? 2 : first - 1]};
  };
  const auto reverseKeyOf = [&](size_t t) {
    const uint32_t* c = &indices[3 * t];
    const CornerKey k = {c[0], c[2], c[1]};
    const size_t first = firstOf(k[0], k[1], k[2]);
    return CornerKey{k[first], k[(first + 1) % 3], k[(first + 2) % 3]};
  };
  std::vector<uint8_t> rotation(count);
  uint32_t vertices = 0;  // one more than the largest first corner: the buckets
  for (size_t t = 0; t < count; ++t) {
    const uint32_t* c = &indices[3 * t];
    rotation[t] = firstOf(c[0], c[1], c[2]);
    vertices = std::max(vertices, c[rotation[t]] + 1);
  }
  // A triangle and its reverse share their smallest corner: triangles are bucketed by it, in
  // triangle order (a counting sort), and each bucket is settled alone, the buckets on
  // `threads` threads. Most buckets hold a handful (the triangles whose smallest corner a
  // vertex is), scanned directly.
  std::vector<uint32_t> start(size_t(vertices) + 1, 0);
  for (size_t t = 0; t < count; ++t) ++start[indices[3 * t + rotation[t]] + 1];
  for (uint32_t v = 0; v < vertices; ++v) start[v + 1] += start[v];
  std::vector<uint32_t> byCorner(count);
  {
    std::vector<uint32_t> next(start.begin(), start.end() - 1);
    for (size_t t = 0; t < count; ++t) byCorner[next[indices[3 * t + rotation[t]]]++] = uint32_t(t);
  }
  // Per bucket, in triangle order: a triangle cancels with the latest open one whose key is
  // its reverse, else stays open. A bucket's triangles are its own, so threads settling other
  // buckets write other bytes (bytes: vector<bool> packs eight triangles into a byte).
  std::vector<uint8_t> cancelled(count, 0);
  constexpr size_t kScanned = 64;  // larger buckets keep their open triangles per key
  // A second thread pays for itself from ~16 thousand triangles on: the buckets take ~40
  // instructions a triangle, a worker's wake-up ~40 µs (a small tree's ~10 thousand are
  // settled here at once).
  const unsigned shares = count < 16384 ? 1 : threads;
  parallelFor(vertices, shares, [&](size_t firstVertex, size_t endVertex) {
    std::vector<uint32_t> open;
    std::map<CornerKey, std::vector<uint32_t>> openByKey;
    for (size_t v = firstVertex; v < endVertex; ++v) {
      const uint32_t* first = byCorner.data() + start[v];
      const uint32_t* last = byCorner.data() + start[v + 1];
      if (last - first < 2) continue;
      const bool scanned = size_t(last - first) <= kScanned;
      open.clear();
      openByKey.clear();
      for (const uint32_t* i = first; i != last; ++i) {
        const uint32_t t = *i;
        const CornerKey reverse = reverseKeyOf(t);
        if (scanned) {
          auto match = std::find_if(open.rbegin(), open.rend(), [&](uint32_t o) {
            const CornerKey k = keyOf(o, rotation[o]);  // compared word by word, not by memcmp
            return k[1] == reverse[1] && k[2] == reverse[2] && k[0] == reverse[0];
          });
          if (match != open.rend()) {
            cancelled[*match] = cancelled[t] = 1;
            open.erase(std::next(match).base());
          } else {
            open.push_back(t);
          }
          continue;
        }
        const auto match = openByKey.find(reverse);
        if (match != openByKey.end() && !match->second.empty()) {
          cancelled[match->second.back()] = cancelled[t] = 1;
          match->second.pop_back();
        } else {
          openByKey[keyOf(t, rotation[t])].push_back(t);
        }
      }
    }
  });
  return cancelled;
}

}  // namespace

std::vector<bool> backToBackPairs(const std::vector<uint32_t>& indices, unsigned threads) {
  const std::vector<uint8_t> cancelled = cancelledFlags(indices, threads);
  return std::vector<bool>(cancelled.begin(), cancelled.end());
}

std::vector<uint32_t> backToBackTriangles(const std::vector<uint32_t>& indices, unsigned threads) {
  const std::vector<uint8_t> cancelled = cancelledFlags(indices, threads);
  std::vector<uint32_t> triangles;
  for (size_t t = 0; t < cancelled.size(); ++t)
    if (cancelled[t]) triangles.push_back(uint32_t(t));
  return triangles;
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
