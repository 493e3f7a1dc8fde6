// Small helpers shared by the benchmarks: timing with min/median over repeats.
#pragma once
#include <algorithm>
#include <functional>
#include <vector>

#include "common/stopwatch.h"

namespace tessera::bench {

// Every timed case runs at least this many times (the issue asks for min and median of ≥ 5).
constexpr int kMinRuns = 5;

struct Timing {
  double minSeconds = 0;
  double medianSeconds = 0;
  int runs = 0;
  double firstSeconds = 0;  // the warm-up run, where a case times one (not in min or median)
};

// Runs `work` once to warm up (pipeline JIT, page faults), then `repeats` (at least
// kMinRuns) times. `beforeEach`, if given, runs before every run outside the timer (e.g. to
// release the previous run's result, as OCCT's cases clean the shape before meshing).
// `steadyAfterSeconds` > 0 runs `work` untimed after the first run until that long has passed
// since it began: for a path that reaches its steady state in the background (rule T's fused
// pipeline, built on a worker once a Tessellator is reused), whose first run is reported apart.
inline Timing timeRepeated(int repeats, const std::function<void()>& work,
                           const std::function<void()>& beforeEach = {},
                           double steadyAfterSeconds = 0) {
  repeats = std::max(repeats, kMinRuns);
  if (beforeEach) beforeEach();
  const Stopwatch first;
  work();
  const double firstSeconds = first.elapsedSeconds();
  while (first.elapsedSeconds() < steadyAfterSeconds) {
    if (beforeEach) beforeEach();
    work();
  }
  std::vector<double> seconds;
  for (int r = 0; r < repeats; ++r) {
    if (beforeEach) beforeEach();
    const Stopwatch stopwatch;
    work();
    seconds.push_back(stopwatch.elapsedSeconds());
  }
  std::sort(seconds.begin(), seconds.end());
  return {seconds.front(), seconds[seconds.size() / 2], repeats, firstSeconds};
}

}  // namespace tessera::bench
