// weldIdenticalPositions (mesh_cleanup.h): per vertex, the first vertex with its position bit
// for bit (−0 and +0 one). Up to 2¹⁷ vertices (the tea set at δ 10⁻³: ~36,000) one
// open-addressed table of vertex indices on the calling thread: a probe compares the position
// in place, where the sharded hash map of firstOccurrences spent about twice the instructions
// (its table's clearing, 12-byte keys, robin-hood bookkeeping) and at 10⁻³ five times the time
// on one thread (0.74 against 0.14 ms). The table's room (at most 2 MiB) is kept by the thread
// from call to call. Whether a warm loop faults its pages in again after malloc trims the heap
// depends on every block of the call, not on this table alone (bench/HISTORY.md, sessions 44
// and 46). Larger meshes keep the map, sharded on all the threads asked for; its tables are
// kept from call to call too.
#include <array>
#include <cstring>

#include "common/first_occurrence.h"
#include "mesh/mesh_cleanup.h"

namespace tessera {
namespace {

using PositionBits = std::array<uint32_t, 3>;

struct PositionBitsHash {
  size_t operator()(const PositionBits& k) const {
    return size_t(k[0] * 0x9E3779B97F4A7C15ull ^ k[1] * 0xC2B2AE3D27D4EB4Full ^
                  k[2] * 0x165667B19E3779F9ull);
  }
};

PositionBits bitsOf(const glm::vec3& p) {
  PositionBits key;
  for (int c = 0; c < 3; ++c) {
    const float x = p[c] == 0.0f ? 0.0f : p[c];  // −0 welds with +0
    std::memcpy(&key[size_t(c)], &x, sizeof x);
  }
  return key;
}

// Up to this many vertices the flat table, at most 2¹⁹ slots (2 MiB), is used.
constexpr size_t kFlatTableVertices = size_t(1) << 17;

std::vector<uint32_t> firstEqualInFlatTable(const std::vector<glm::vec3>& positions) {
  const size_t count = positions.size();
  std::vector<uint32_t> first(count);
  // At most a quarter full: a new position mostly meets an empty slot first. Two thirds full
  // took twice the time (δ 0.01: 0.027 against 0.013 ms), mostly mispredicted probe loops.
  int bits = 4;
  while ((size_t(1) << bits) < 4 * count) ++bits;
  const size_t mask = (size_t(1) << bits) - 1;
  constexpr uint32_t kEmpty = UINT32_MAX;
  // Its room only, filled anew every call: a new block of up to 2 MiB every call can be
  // mapped afresh (malloc's mmap threshold) or trimmed away, and fault its pages in again.
  thread_local std::vector<uint32_t> table;
  table.assign(mask + 1, kEmpty);
  for (size_t i = 0; i < count; ++i) {
    const PositionBits key = bitsOf(positions[i]);
    const uint64_t h = uint64_t(PositionBitsHash{}(key)) * 0x9E3779B97F4A7C15ull;
    for (size_t slot = size_t(h >> (64 - bits));; slot = (slot + 1) & mask) {
      const uint32_t j = table[slot];
      if (j == kEmpty) {
        table[slot] = uint32_t(i);
        first[i] = uint32_t(i);
        break;
      }
      if (bitsOf(positions[j]) == key) {
        first[i] = j;
        break;
      }
    }
  }
  return first;
}

}  // namespace

std::vector<uint32_t> weldIdenticalPositions(const std::vector<glm::vec3>& positions,
                                             unsigned threads) {
  if (positions.size() <= kFlatTableVertices) return firstEqualInFlatTable(positions);
  const auto forEachKey = [&](auto&& visit) {
    for (size_t i = 0; i < positions.size(); ++i) visit(i, bitsOf(positions[i]));
  };
  return firstOccurrences<PositionBits, PositionBitsHash>(positions.size(), positions.size(),
                                                          forEachKey, threads);
}

}  // namespace tessera
