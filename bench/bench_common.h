// Small helpers shared by the benchmarks: timing with min/median over repeats.
#pragma once
#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

namespace tessera::bench {

// Every timed case runs at least this many times (the issue asks for min and median of ≥ 5).
constexpr int kMinRuns = 5;

struct Timing {
  double minSeconds = 0;
  double medianSeconds = 0;
  int runs = 0;
};

inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Runs `work` once to warm up (pipeline JIT, page faults), then `repeats` (at least
// kMinRuns) times.
inline Timing timeRepeated(int repeats, const std::function<void()>& work) {
  repeats = std::max(repeats, kMinRuns);
  work();
  std::vector<double> seconds;
  for (int r = 0; r < repeats; ++r) {
    auto start = std::chrono::steady_clock::now();
    work();
    seconds.push_back(secondsSince(start));
  }
  std::sort(seconds.begin(), seconds.end());
  return {seconds.front(), seconds[seconds.size() / 2], repeats};
}

}  // namespace tessera::bench
