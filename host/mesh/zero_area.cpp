#include "mesh/zero_area.h"

#include <algorithm>
#include <array>
#include <unordered_map>

#include "common/parallel_for.h"

namespace tessera {
namespace {

uint64_t edgeKey(uint32_t a, uint32_t b) { return (uint64_t(a) << 32) | b; }

// Whether p, on the line through a and b, lies strictly between them.
bool strictlyBetween(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
  const glm::dvec3 ab = glm::dvec3(b) - glm::dvec3(a), ap = glm::dvec3(p) - glm::dvec3(a);
  const double t = glm::dot(ap, ab);
  return t > 0.0 && t < glm::dot(ab, ab) && p != a && p != b;
}

// zeroArea's test, inlined into the scan of every triangle (a call each was ~40% of the scan).
[[gnu::always_inline]] inline bool crossIsZero(const glm::vec3& a, const glm::vec3& b,
                                               const glm::vec3& c) {
  const glm::dvec3 n = glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a));
  return n.x == 0.0 && n.y == 0.0 && n.z == 0.0;
}

}  // namespace

bool zeroArea(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  return crossIsZero(a, b, c);
}

std::vector<bool> removeCaps(const std::vector<glm::vec3>& positions,
                             std::vector<uint32_t>& indices, std::vector<uint32_t>& trianglePatch,
                             std::vector<glm::vec2>& cornerUv, unsigned threads) {
  std::vector<bool> removed(indices.size() / 3, false);
  for (uint32_t t : removeCapTriangles(positions, indices, trianglePatch, cornerUv, threads))
    removed[t] = true;
  return removed;
}

std::vector<uint32_t> removeCapTriangles(const std::vector<glm::vec3>& positions,
                                         std::vector<uint32_t>& indices,
                                         std::vector<uint32_t>& trianglePatch,
                                         std::vector<glm::vec2>& cornerUv, unsigned threads) {
  const size_t count = indices.size() / 3;
  const auto corner = [&](size_t t, int k) { return indices[3 * t + size_t(k)]; };
  const auto isCap = [&](size_t t) {
    return crossIsZero(positions[corner(t, 0)], positions[corner(t, 1)], positions[corner(t, 2)]);
  };
  // The caps in triangle order, found on `threads` threads: each share's own list, in turn.
  constexpr size_t kShare = 8192;
  std::vector<std::vector<size_t>> found((count + kShare - 1) / kShare);
  parallelForChunks(found.size(), 1, count < 2 * kShare ? 1 : threads,
                    [&](size_t begin, size_t end) {
                      for (size_t share = begin; share < end; ++share)
                        for (size_t t = share * kShare; t < std::min(count, (share + 1) * kShare); ++t)
                          if (isCap(t)) found[share].push_back(t);
                    });
  std::vector<size_t> caps;
  for (const std::vector<size_t>& share : found) caps.insert(caps.end(), share.begin(), share.end());
  if (caps.empty()) return {};
  std::vector<bool> removed(count, false);

  std::unordered_map<uint64_t, uint32_t> owner;  // directed edge → its triangle
  owner.reserve(indices.size());
  for (size_t t = 0; t < count; ++t)
    for (int k = 0; k < 3; ++k) owner[edgeKey(corner(t, k), corner(t, (k + 1) % 3))] = uint32_t(t);
  const auto hasEdge = [&](uint32_t a, uint32_t b) {
    return owner.count(edgeKey(a, b)) || owner.count(edgeKey(b, a));
  };
  const auto setTriangle = [&](size_t t, std::array<uint32_t, 3> v, uint32_t patch,
                               std::array<glm::vec2, 3> uv) {
    for (int k = 0; k < 3; ++k) {
      indices[3 * t + size_t(k)] = v[size_t(k)];
      cornerUv[3 * t + size_t(k)] = uv[size_t(k)];
      owner[edgeKey(v[size_t(k)], v[size_t(k + 1) % 3])] = uint32_t(t);
    }
    trianglePatch[t] = patch;
  };
  const auto forget = [&](size_t t) {
    for (int k = 0; k < 3; ++k) owner.erase(edgeKey(corner(t, k), corner(t, (k + 1) % 3)));
  };

  // The passes end: each change lowers the sum of the caps' long edges (a flip off the line
  // or a removal takes one cap away; a flip into a cap over the same edge turns two caps of
  // length L into two over parts of it), which takes finitely many values.
  for (bool changed = true; changed;) {
    changed = false;
    for (size_t t : caps) {
      if (removed[t] || !isCap(t)) continue;
      // Rotate to (a, b, m): a→b the long edge, m between a and b.
      int longest = 0;
      double length = -1;
      for (int k = 0; k < 3; ++k) {
        const double l = glm::length(glm::dvec3(positions[corner(t, (k + 1) % 3)]) -
                                     glm::dvec3(positions[corner(t, k)]));
        if (l > length) length = l, longest = k;
      }
      const uint32_t a = corner(t, longest), b = corner(t, (longest + 1) % 3),
                     m = corner(t, (longest + 2) % 3);
      const auto across = owner.find(edgeKey(b, a));
      if (across == owner.end()) {  // on an open edge: the boundary runs a, m, b instead
        forget(t);
        removed[t] = true;
        changed = true;
        continue;
      }
      const size_t n = across->second;
      int at = 0;  // n is (b, a, d) from corner `at`
      while (corner(n, at) != b) ++at;
      const uint32_t d = corner(n, (at + 2) % 3);
      // Into a neighbour off the line, or one that is a cap over the same long edge (d between
      // a and b: both become caps over shorter edges, which later flips take further).
      if (hasEdge(m, d) || (zeroArea(positions[a], positions[b], positions[d]) &&
                            !strictlyBetween(positions[d], positions[a], positions[b])))
        continue;
      const glm::vec2 ua = cornerUv[3 * n + size_t((at + 1) % 3)], ub = cornerUv[3 * n + size_t(at)],
                      ud = cornerUv[3 * n + size_t((at + 2) % 3)];
      const double s = glm::length(glm::dvec3(positions[m]) - glm::dvec3(positions[a])) / length;
      const glm::vec2 um = ua + float(s) * (ub - ua);
      const uint32_t patch = trianglePatch[n];
      forget(t);
      forget(n);
      setTriangle(t, {m, a, d}, patch, {um, ua, ud});
      setTriangle(n, {m, d, b}, patch, {um, ud, ub});
      changed = true;
    }
  }
  std::vector<uint32_t> gone;  // ascending: `caps` is
  for (size_t t : caps)
    if (removed[t]) gone.push_back(uint32_t(t));
  return gone;
}

}  // namespace tessera
