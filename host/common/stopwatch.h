// Wall-clock timing for the stats the stages report: one steady clock, read in milliseconds
// or seconds, instead of the duration arithmetic written out at every call site.
#pragma once

#include <chrono>

namespace tessera {

class Stopwatch {
 public:
  Stopwatch() : start_(Clock::now()) {}

  // Starts counting again from now.
  void restart() { start_ = Clock::now(); }

  double elapsedMs() const {
    return std::chrono::duration<double, std::milli>(Clock::now() - start_).count();
  }

  double elapsedSeconds() const {
    return std::chrono::duration<double>(Clock::now() - start_).count();
  }

 private:
  // steady_clock never runs backwards, so an elapsed time is never negative.
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_;
};

}  // namespace tessera
