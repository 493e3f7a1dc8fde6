// Progress of long work as lines on stderr ("tessera: quad-tree level 7, 63.2% of the
// patches settled, 81234 nodes classified"), at most one every few seconds, whether or not
// stderr is a terminal (a log file or CI output shows that the run is alive). Quiet with -q.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "common/stopwatch.h"
#include "quadtree/quadtree.h"

namespace tessera::cli {

// Seconds between progress lines: 2, or TESSERA_PROGRESS_INTERVAL (seconds, ≥ 0; 0 prints
// every update, which the tests use). A malformed value is ignored.
double progressIntervalSeconds();

class Progress {
 public:
  // `enabled` false (-q) prints nothing.
  Progress(bool enabled, double intervalSeconds);

  // Prints "tessera: <message>" if the interval has passed since the last line (or the start).
  void update(const std::string& message);

  // The quad-tree's progress for QuadtreeOptions::onLevel over `patchCount` patches. The
  // measure is the share of the trees settled: a root weighs 1, each split hands a quarter of
  // its node's weight to each child, and a leaf's weight is settled. It reaches 100% exactly
  // when the tree is done, and for the midpoint rule it is the parameter area settled. Deep
  // levels hold many small nodes, so it rises fast and ends slowly; the line also counts the
  // nodes classified, which grows with the work done.
  std::function<void(const LevelStats&)> treeCallback(size_t patchCount);

 private:
  bool enabled_;
  double intervalSeconds_;
  Stopwatch sinceLastLine_;
  std::vector<LevelStats> seen_;  // per level, the totals already counted
  double settled_ = 0;            // Σ leaf weights, in root units
  size_t classified_ = 0;         // nodes classified, all levels
};

}  // namespace tessera::cli
