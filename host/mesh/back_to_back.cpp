// backToBackPairs and backToBackTriangles (mesh_cleanup.h). A triangle and its reverse have
// one set of corners, so only triangles whose corner set another triangle may share can
// cancel: a bit table of the sets' hashes finds those candidates in two passes. The candidates
// (on the tea set at δ 0.01 ~700 of 9,583 triangles, hash collisions all) are then grouped by
// corner set and each group is settled in triangle order, which is the rule's order: a match
// only ever joins two triangles of one set. This replaced a bucketing of every triangle by its
// smallest corner: ~80 instructions a triangle instead of ~145, half the time (bench/HISTORY.md).
#include <algorithm>
#include <array>
#include <map>

#include "common/parallel_for.h"
#include "mesh/mesh_cleanup.h"

namespace tessera {
namespace {

using Corners = std::array<uint32_t, 3>;

Corners sortedCorners(const uint32_t* c) {
  const uint32_t lo = std::min(c[0], c[1]), hi = std::max(c[0], c[1]);
  return {std::min(lo, c[2]), std::max(lo, std::min(hi, c[2])), std::max(hi, c[2])};
}

// A hash of a triangle's corner set: the same for its corners in any order, without sorting
// them (a sort cost more than the rest of the pass).
uint64_t cornerSetHash(const uint32_t* c) {
  const auto mix = [](uint64_t x) {
    x *= 0x9E3779B97F4A7C15ull;
    return x ^ (x >> 29);
  };
  return (mix(c[0]) + mix(c[1]) + mix(c[2])) * 0xC2B2AE3D27D4EB4Full;
}

// The triangles whose corner set's hash another triangle's shares, ascending: every triangle
// that has its reverse in the mesh, and a few whose hashes collide.
std::vector<uint32_t> sharedCornerSets(const std::vector<uint32_t>& indices) {
  const size_t count = indices.size() / 3;
  // At least 16 bits a triangle: about one triangle in sixteen collides with another's hash.
  int bits = 6;
  while ((size_t(1) << bits) < 16 * count) ++bits;
  const size_t words = (size_t(1) << bits) / 64;
  // The bit table and the first pass's slots, held for the second pass, in room the thread
  // keeps from call to call up to kKeptTriangles (1 MiB: no block of that size allocated and
  // freed every call for malloc to trim); a larger mesh's slots are hashed again.
  constexpr size_t kKeptTriangles = size_t(1) << 17;
  const bool kept = count <= kKeptTriangles;
  thread_local std::vector<uint64_t> keptSeen;
  thread_local std::vector<uint32_t> keptSlots;
  std::vector<uint64_t> ownSeen;
  std::vector<uint64_t>& seen = kept ? keptSeen : ownSeen;
  seen.assign(2 * words, 0);  // [0, words): once; [words, 2 words): again
  uint64_t* const once = seen.data();
  uint64_t* const again = seen.data() + words;
  const auto slotOf = [&](size_t t) {
    return uint32_t(cornerSetHash(&indices[3 * t]) >> (64 - bits));
  };
  if (kept) keptSlots.resize(count);
  uint32_t* const slots = kept ? keptSlots.data() : nullptr;
  bool anyAgain = false;
  for (size_t t = 0; t < count; ++t) {
    const uint32_t slot = slotOf(t);
    if (slots) slots[t] = slot;
    const uint64_t bit = uint64_t(1) << (slot % 64);
    if (once[slot / 64] & bit) again[slot / 64] |= bit, anyAgain = true;
    once[slot / 64] |= bit;
  }
  std::vector<uint32_t> candidates;
  if (!anyAgain) return candidates;
  for (size_t t = 0; t < count; ++t) {
    const uint32_t slot = slots ? slots[t] : slotOf(t);
    if (again[slot / 64] & (uint64_t(1) << (slot % 64))) candidates.push_back(uint32_t(t));
  }
  return candidates;
}

// Settles one corner set's triangles [first, last), in triangle order: a triangle cancels with
// the latest open one whose corners, rotated to start at the smallest, are its own reversed;
// otherwise it stays open.
void settle(const std::vector<uint32_t>& indices, const uint32_t* first, const uint32_t* last,
            std::vector<uint8_t>& cancelled, std::vector<uint32_t>& open,
            std::map<Corners, std::vector<uint32_t>>& openByKey) {
  // Which rotation starts at the smallest corner (the first of equal ones).
  const auto firstOf = [](uint32_t a, uint32_t b, uint32_t c) -> size_t {
    return b < a ? (c < b ? 2 : 1) : (c < a ? 2 : 0);
  };
  const auto keyOf = [&](uint32_t t) {
    const uint32_t* c = &indices[3 * size_t(t)];
    const size_t f = firstOf(c[0], c[1], c[2]);
    return Corners{c[f], c[(f + 1) % 3], c[(f + 2) % 3]};
  };
  const auto reverseKeyOf = [&](uint32_t t) {
    const uint32_t* c = &indices[3 * size_t(t)];
    const Corners k = {c[0], c[2], c[1]};
    const size_t f = firstOf(k[0], k[1], k[2]);
    return Corners{k[f], k[(f + 1) % 3], k[(f + 2) % 3]};
  };
  constexpr size_t kScanned = 64;  // larger sets keep their open triangles per key
  if (size_t(last - first) <= kScanned) {
    open.clear();
    for (const uint32_t* i = first; i != last; ++i) {
      const Corners reverse = reverseKeyOf(*i);
      const auto match =
          std::find_if(open.rbegin(), open.rend(), [&](uint32_t o) { return keyOf(o) == reverse; });
      if (match != open.rend()) {
        cancelled[*match] = cancelled[*i] = 1;
        open.erase(std::next(match).base());
      } else {
        open.push_back(*i);
      }
    }
    return;
  }
  openByKey.clear();
  for (const uint32_t* i = first; i != last; ++i) {
    const auto match = openByKey.find(reverseKeyOf(*i));
    if (match != openByKey.end() && !match->second.empty()) {
      cancelled[match->second.back()] = cancelled[*i] = 1;
      match->second.pop_back();
    } else {
      openByKey[keyOf(*i)].push_back(*i);
    }
  }
}

// Per triangle, 1 when it cancels with its reverse (bytes: groups settled on several threads
// write bytes of their own); empty when none does for want of candidates.
std::vector<uint8_t> cancelledFlags(const std::vector<uint32_t>& indices, unsigned threads) {
  std::vector<uint32_t> candidates = sharedCornerSets(indices);
  if (candidates.empty()) return {};
  std::vector<uint8_t> cancelled(indices.size() / 3, 0);
  // By corner set, each set's triangles in triangle order.
  std::vector<std::pair<Corners, uint32_t>> keyed(candidates.size());
  for (size_t k = 0; k < candidates.size(); ++k)
    keyed[k] = {sortedCorners(&indices[3 * size_t(candidates[k])]), candidates[k]};
  std::sort(keyed.begin(), keyed.end());
  std::vector<size_t> groupStart;
  for (size_t k = 0; k < keyed.size(); ++k) {
    candidates[k] = keyed[k].second;
    if (k == 0 || keyed[k].first != keyed[k - 1].first) groupStart.push_back(k);
  }
  groupStart.push_back(keyed.size());
  // A second thread pays for itself only on many candidates (a worker's wake-up is ~40 µs).
  const unsigned shares = candidates.size() < 16384 ? 1 : threads;
  parallelFor(groupStart.size() - 1, shares, [&](size_t firstGroup, size_t endGroup) {
    std::vector<uint32_t> open;
    std::map<Corners, std::vector<uint32_t>> openByKey;
    for (size_t g = firstGroup; g < endGroup; ++g)
      settle(indices, candidates.data() + groupStart[g], candidates.data() + groupStart[g + 1],
             cancelled, open, openByKey);
  });
  return cancelled;
}

}  // namespace

std::vector<bool> backToBackPairs(const std::vector<uint32_t>& indices, unsigned threads) {
  const std::vector<uint8_t> cancelled = cancelledFlags(indices, threads);
  if (cancelled.empty()) return std::vector<bool>(indices.size() / 3, false);
  return std::vector<bool>(cancelled.begin(), cancelled.end());
}

std::vector<uint32_t> backToBackTriangles(const std::vector<uint32_t>& indices, unsigned threads) {
  const std::vector<uint8_t> cancelled = cancelledFlags(indices, threads);
  std::vector<uint32_t> triangles;
  for (size_t t = 0; t < cancelled.size(); ++t)
    if (cancelled[t]) triangles.push_back(uint32_t(t));
  return triangles;
}

}  // namespace tessera
