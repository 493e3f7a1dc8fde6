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
};

// Runs `work` once to warm up (pipeline JIT, page faults), then `repeats` (at least
// kMinRuns) times.
inline Timing timeRepeated(int repeats, const std::function<void()>& work) {
  repeats = std::max(repeats, kMinRuns);
  work();
  std::vector<double> seconds;
  for (int r = 0; r < repeats; ++r) {
    const Stopwatch stopwatch;
    work();
    seconds.push_back(stopwatch.elapsedSeconds());
  }
  std::sort(seconds.begin(), seconds.end());
  return {seconds.front(), seconds[seconds.size() / 2], repeats};
}

}  // namespace tessera::bench
