#include "tree_divergence.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace tessera::test {
namespace {

using NodeKey = std::tuple<uint32_t, uint32_t, uint64_t>;  // patch, level, path

uint64_t prefix(uint64_t path, uint32_t level) {
  return level >= 32 ? path : (path & ((uint64_t(1) << (2 * level)) - 1));
}

struct TreeIndex {
  std::map<NodeKey, const QuadLeaf*> leaves;
  std::map<NodeKey, gpu::vec4> rects;  // every node, internal ones as the box of their leaves

  explicit TreeIndex(const QuadtreeResult& tree) {
    for (const QuadLeaf& leaf : tree.leaves) {
      leaves[{leaf.patchIndex, leaf.level, leaf.path}] = &leaf;
      for (uint32_t k = 0; k <= leaf.level; ++k) {
        NodeKey key{leaf.patchIndex, k, prefix(leaf.path, k)};
        auto it = rects.find(key);
        if (it == rects.end()) {
          rects[key] = leaf.rect;
        } else {
          gpu::vec4& r = it->second;
          r = gpu::vec4(std::min(r.x, leaf.rect.x), std::min(r.y, leaf.rect.y),
                        std::max(r.z, leaf.rect.z), std::max(r.w, leaf.rect.w));
        }
      }
    }
  }
};

// A test value near its threshold, or a node whose size is at the minimum (its rectangle
// carries fp32 vs double rounding of every split point above it).
bool nearThreshold(const QuadLeaf& leaf, const QuadtreeOptions& o, double band) {
  double size = std::min(leaf.rect.z - leaf.rect.x, leaf.rect.w - leaf.rect.y);
  return std::fabs(leaf.linearity - o.linearity) <= band ||
         std::fabs(leaf.flatness - o.flatness) <= band ||
         (leaf.cause == gpu::kCauseMinSize && std::fabs(size - o.minSize) <= 1e-2 * o.minSize);
}

void explain(const NodeKey& node, const QuadLeaf& leaf, const TreeIndex& a, const TreeIndex& b,
             const QuadtreeOptions& o, double band, std::set<NodeKey>& seen,
             DivergenceReport& report) {
  if (!seen.insert(node).second) return;
  gpu::vec4 ra = a.rects.at(node), rb = b.rects.at(node);
  double moved = std::max({std::fabs(ra.x - rb.x), std::fabs(ra.y - rb.y),
                           std::fabs(ra.z - rb.z), std::fabs(ra.w - rb.w)});
  // Relative to the node's narrow side: 1e-3 of a sliver's width is a real move.
  double narrow = std::min({ra.z - ra.x, ra.w - ra.y, rb.z - rb.x, rb.w - rb.y});
  if (moved > 1e-3 * narrow) {
    ++report.moved;
  } else if (nearThreshold(leaf, o, band)) {
    ++report.ambiguous;
  } else {
    ++report.unexplained;
    if (report.firstUnexplained.empty()) {
      std::ostringstream s;
      s << "patch " << std::get<0>(node) << " level " << std::get<1>(node) << " size " << (leaf.rect.z - leaf.rect.x) << "x" << (leaf.rect.w - leaf.rect.y) << " split " << leaf.split.x << "," << leaf.split.y << " rect " << leaf.rect.x << "," << leaf.rect.y << " linearity "
        << leaf.linearity << " flatness " << leaf.flatness << " cause " << leaf.cause;
      report.firstUnexplained = s.str();
    }
  }
}

// Leaves of `x` missing from `y`: find where the trees part and explain it.
void walk(const TreeIndex& x, const TreeIndex& y, const QuadtreeOptions& o, double band,
          std::set<NodeKey>& seen, DivergenceReport& report, bool countMatches) {
  for (const auto& [key, leaf] : x.leaves) {
    if (y.leaves.count(key)) {
      if (countMatches) ++report.matchedLeaves;
      continue;
    }
    auto [patch, level, path] = key;
    bool ancestorLeaf = false;
    for (uint32_t k = 0; k < level; ++k) {
      NodeKey up{patch, k, prefix(path, k)};
      auto it = y.leaves.find(up);
      if (it != y.leaves.end()) {  // y stopped at an ancestor that x split
        explain(up, *it->second, x, y, o, band, seen, report);
        ancestorLeaf = true;
        break;
      }
    }
    if (!ancestorLeaf) explain(key, *leaf, x, y, o, band, seen, report);  // y split further
  }
}

}  // namespace

DivergenceReport compareTrees(const QuadtreeResult& a, const QuadtreeResult& b,
                              const QuadtreeOptions& options, double band) {
  DivergenceReport report;
  report.leavesA = a.leaves.size();
  report.leavesB = b.leaves.size();
  TreeIndex ia(a), ib(b);
  std::set<NodeKey> seen;
  walk(ia, ib, options, band, seen, report, true);
  walk(ib, ia, options, band, seen, report, false);
  return report;
}

void requireExplainedDivergence(const QuadtreeResult& a, const QuadtreeResult& b,
                                const QuadtreeOptions& options, double band,
                                const std::string& what, const char* nameA, const char* nameB) {
  const DivergenceReport r = compareTrees(a, b, options, band);
  WARN(what << " rule " << splitRuleLetter(options.rule) << " threshold " << options.flatness
            << ": " << nameA << " " << r.leavesA << " leaves, " << nameB << " " << r.leavesB
            << ", matched "
            << r.matchedLeaves << "; diverging nodes: " << r.ambiguous << " within the band, "
            << r.moved << " moved, " << r.unexplained << " unexplained " << r.firstUnexplained);
  REQUIRE(r.unexplained == 0);
  if (options.rule == SplitRule::Midpoint) REQUIRE(r.moved == 0);  // midpoints are exact in both
}

}  // namespace tessera::test
