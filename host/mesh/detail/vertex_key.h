// What the triangulator (triangulate.cpp and the mesh/ files it is split into) calls a vertex
// before it has an index: a key that every leaf meeting the point builds alike, so that one
// lookup welds them (docs/watertight.md). Shared by the setup (seam_vertices, line_points,
// near_point_merge), the leaf walk and the numbering.
#pragma once
#include <cstdint>
#include <cstring>

namespace tessera::triangulate_detail {

inline uint32_t bits(float x) {
  uint32_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

inline float fromBits(uint32_t b) {
  float x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}

enum KeyKind : uint32_t { kPatchParam, kEdgeParam, kPosition, kFoldPosition };

struct VertexKey {
  uint32_t kind;
  uint32_t a;  // patch, edge group, position id, or folded side
  uint64_t b;  // (u bits, v bits), canonical t bits, 0, or the position along the fold's line
  bool operator==(const VertexKey& o) const { return kind == o.kind && a == o.a && b == o.b; }
};

struct VertexKeyHash {
  size_t operator()(const VertexKey& k) const {
    uint64_t h = (uint64_t(k.kind) << 32 | k.a) * 0x9E3779B97F4A7C15ull;
    return size_t(h ^ (k.b + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2)));
  }
};

// A line u = const or v = const of a patch, as LineIndex keys it: the patch and the constant.
inline uint64_t lineKey(uint32_t patch, float coordinate) {
  return (uint64_t(patch) << 32) | bits(coordinate);
}

}  // namespace tessera::triangulate_detail
