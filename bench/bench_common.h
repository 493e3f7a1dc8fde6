// Small helpers shared by the benchmarks: timing with min/median over repeats.
#pragma once
#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

namespace tessera::bench {

struct Timing {
  double minSeconds = 0;
  double medianSeconds = 0;
};

// Runs `work` once to warm up (pipeline JIT, page faults), then `repeats` times.
inline Timing timeRepeated(int repeats, const std::function<void()>& work) {
  work();
  std::vector<double> seconds;
  for (int r = 0; r < repeats; ++r) {
    auto start = std::chrono::steady_clock::now();
    work();
    seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(seconds.begin(), seconds.end());
  return {seconds.front(), seconds[seconds.size() / 2]};
}

}  // namespace tessera::bench
