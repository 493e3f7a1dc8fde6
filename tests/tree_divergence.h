// Explains every difference between two quad-trees of the same patches (e.g. fp32 vs double):
// a node that is a leaf in one tree and split in the other is "ambiguous" when one of its test
// values lies within `band` of its threshold, "moved" when its rectangle differs between the
// trees (an ancestor's split point moved, as C and D may do at near-ties of κ), and
// "unexplained" otherwise.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <tuple>

#include "quadtree/quadtree.h"

namespace tessera::test {

struct DivergenceReport {
  size_t leavesA = 0, leavesB = 0, matchedLeaves = 0;
  size_t ambiguous = 0, moved = 0, unexplained = 0;
  std::string firstUnexplained;
};

DivergenceReport compareTrees(const QuadtreeResult& a, const QuadtreeResult& b,
                              const QuadtreeOptions& options, double band);

// Prints the report of the fp32 tree `a` against the double tree `b` (labelled with `what`,
// the options' rule and threshold) and requires every divergence explained; with the
// midpoint rule no node may move either (midpoints are exact in both).
void requireExplainedDivergence(const QuadtreeResult& a, const QuadtreeResult& b,
                                const QuadtreeOptions& options, double band,
                                const std::string& what, const char* nameA = "fp32",
                                const char* nameB = "double");

}  // namespace tessera::test
