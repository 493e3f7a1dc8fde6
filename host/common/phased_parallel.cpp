#include "common/phased_parallel.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

#include "common/parallel_for.h"

namespace tessera {
namespace {

// How long a thread with nothing to take yields before it sleeps: about a sleeper's wake-up
// under load (120-370 µs), so the serial steps and short tails cost no wake-up, while a long
// last item (a big face) does not hold yielding cores from the caller's other threads.
constexpr std::chrono::microseconds kYieldBeforeSleeping{250};

// The shared hand-out of one runPhases call. The state is under `mutex_`; `epoch_` changes
// (under it) whenever a phase opens or the run ends, so a waiting thread can watch it unlocked.
class PhaseRunner {
 public:
  explicit PhaseRunner(const std::vector<ParallelPhase>& phases) : phases_(phases) {}

  void start() {
    std::unique_lock<std::mutex> lock(mutex_);
    open(0, lock);
  }

  // One thread's part: chunks of the open phase until every phase has ended.
  void work() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (phase_ < phases_.size()) {
      if (next_ < count_) {
        const size_t begin = next_, end = std::min(count_, begin + chunk_);
        next_ = end;
        const ParallelPhase& phase = phases_[phase_];
        lock.unlock();
        runItems(phase, begin, end);
        lock.lock();
        finished_ += end - begin;
        if (finished_ == count_) close(lock);
        continue;
      }
      // Every item is taken and another thread is finishing one or running the `then`.
      const size_t seen = epoch_.load(std::memory_order_relaxed);
      lock.unlock();
      const auto sleepAt = std::chrono::steady_clock::now() + kYieldBeforeSleeping;
      while (epoch_.load(std::memory_order_acquire) == seen &&
             std::chrono::steady_clock::now() < sleepAt)
        std::this_thread::yield();
      lock.lock();
      epochChanged_.wait(lock, [&] { return epoch_.load(std::memory_order_relaxed) != seen; });
    }
  }

  bool ended() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return phase_ == phases_.size();
  }

  void rethrow() const {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  void runItems(const ParallelPhase& phase, size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      try {
        phase.item(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (!phaseError_ || i < phaseErrorItem_) {
          phaseError_ = std::current_exception();
          phaseErrorItem_ = i;
        }
      }
    }
  }

  // The open phase's items have all finished (the lock held): its lowest item's exception ends
  // the run, else its `then` runs and the next phase opens.
  void close(std::unique_lock<std::mutex>& lock) {
    std::exception_ptr failure = phaseError_;
    const ParallelPhase& phase = phases_[phase_];
    if (!failure && phase.then) {
      lock.unlock();
      try {
        phase.then();
      } catch (...) {
        failure = std::current_exception();
      }
      lock.lock();
    }
    if (failure) return end(failure);
    open(phase_ + 1, lock);
  }

  // Opens phase p, or the first after it with items: a phase without items only runs its `then`.
  void open(size_t p, std::unique_lock<std::mutex>& lock) {
    for (; p < phases_.size(); ++p) {
      const ParallelPhase& phase = phases_[p];
      size_t count = 0;
      lock.unlock();
      std::exception_ptr failure;
      try {
        count = phase.count();
        if (count == 0 && phase.then) phase.then();
      } catch (...) {
        failure = std::current_exception();
      }
      lock.lock();
      if (failure) return end(failure);
      if (count > 0) {
        phase_ = p, count_ = count, chunk_ = std::max<size_t>(phase.chunk, 1);
        next_ = finished_ = 0;
        phaseError_ = nullptr;
        epoch_.fetch_add(1, std::memory_order_release);
        epochChanged_.notify_all();
        return;
      }
    }
    end(nullptr);
  }

  void end(std::exception_ptr failure) {
    error_ = failure;
    phase_ = phases_.size();
    epoch_.fetch_add(1, std::memory_order_release);
    epochChanged_.notify_all();
  }

  const std::vector<ParallelPhase>& phases_;
  std::mutex mutex_;
  std::atomic<size_t> epoch_{0};
  std::condition_variable epochChanged_;  // for threads that yielded kYieldBeforeSleeping
  size_t phase_ = 0, count_ = 0, chunk_ = 1, next_ = 0, finished_ = 0;
  std::exception_ptr phaseError_, error_;
  size_t phaseErrorItem_ = 0;
};

}  // namespace

void runPhases(const std::vector<ParallelPhase>& phases, unsigned threads) {
  PhaseRunner runner(phases);
  runner.start();  // on the caller, before a worker is woken: the first count and empty phases
  if (!runner.ended()) parallelParts(resolveThreadCount(threads), [&](unsigned) { runner.work(); });
  runner.rethrow();
}

}  // namespace tessera
