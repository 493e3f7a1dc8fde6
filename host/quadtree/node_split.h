// How a classified node divides into children: the frontier's one place for it, so every
// backend's tree (and the tests that walk trees level by level) make the same children.
#pragma once
#include <cstdint>
#include <vector>

#include "shaders/layout.h"

namespace tessera {

// Children per direction a decision asks for: 1 = that direction is not split; {0, 0} for a
// leaf. kCauseSplit: 2 × 2 at NodeDecision.split; kCauseSplitU / V: 2 × 1 / 1 × 2 there;
// kCauseSplitGrid (rule T): the counts in NodeDecision.pad, equal parts. Throws
// std::logic_error for grid counts outside 1..kToleranceSplitCapMax.
struct SplitCounts {
  uint32_t u = 0, v = 0;
  bool splits() const { return u > 0; }
};
// Throws the std::logic_error of splitCounts for a grid split's counts `pad`.
[[noreturn]] void throwBadGridCounts(uint32_t pad);
// Inline, its error path out of line: the frontier asks twice per node of every level, and a
// call that saves registers for the message's strings took ~26 instructions for a switch.
inline SplitCounts splitCounts(const gpu::NodeDecision& d) {
  switch (d.cause) {
    case gpu::kCauseSplit: return {2, 2};
    case gpu::kCauseSplitU: return {2, 1};
    case gpu::kCauseSplitV: return {1, 2};
    case gpu::kCauseSplitGrid: {
      const uint32_t u = d.pad & 0xFFu, v = d.pad >> 8;
      if (u < 1 || v < 1 || u > gpu::kToleranceSplitCapMax || v > gpu::kToleranceSplitCapMax ||
          u * v < 2)
        throwBadGridCounts(d.pad);
      return {u, v};
    }
    default: return {};
  }
}

// Bits of a child's code along a direction split into `count` parts: ⌈log₂ count⌉.
inline uint32_t pathCodeBits(uint32_t count) {
  uint32_t bits = 0;
  while ((uint32_t(1) << bits) < count) ++bits;
  return bits;
}

// Line i of `count` equal parts of [lo, hi]: lo + (hi − lo)·(i/count), exactly hi at i = count.
// A fixed function of the parent's interval and i, so every child computes the same bits for a
// line it shares with a sibling, and the outer lines are the parent's own.
float equalSplitLine(float lo, float hi, uint32_t i, uint32_t count);

// Appends the children of `node` (split as `counts` asks, `decision` giving the split point of
// a two-way split) at level node.level + 1, rows of v outer and u inner: child k is
// (i, j) = (k mod counts.u, k div counts.u) with path code i | j << pathCodeBits(counts.u).
// Returns false and appends nothing when fp32 cannot place the lines strictly increasing
// (the node then ends as a kCauseMinSize leaf).
bool appendChildren(const gpu::QuadNode& node, const gpu::NodeDecision& decision,
                    SplitCounts counts, std::vector<gpu::QuadNode>& out);

}  // namespace tessera
