// ScopedThreadCap (common/thread_cap.h): under a cap of 1 every share of a parallel loop runs on
// the calling thread and no worker runs a part; a cap follows a part onto the worker that runs
// it, so loops nested in it obey it; scopes combine (the smaller non-zero) and restore.
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

#include "common/parallel_for.h"
#include "common/thread_cap.h"
#include "common/worker_pool.h"

using namespace tessera;

TEST_CASE("thread cap: scopes combine, the smaller non-zero, and restore", "[common][threads]") {
  REQUIRE(threadCap() == 0);
  {
    const ScopedThreadCap outer(3);
    REQUIRE(threadCap() == 3);
    REQUIRE(resolveThreadCount(8) == 3);
    REQUIRE(resolveThreadCount(2) == 2);
    {
      const ScopedThreadCap none(0);  // adds no cap, lifts none
      REQUIRE(threadCap() == 3);
      const ScopedThreadCap wider(5);
      REQUIRE(threadCap() == 3);
      const ScopedThreadCap narrower(2);
      REQUIRE(threadCap() == 2);
    }
    REQUIRE(threadCap() == 3);
  }
  REQUIRE(threadCap() == 0);
  REQUIRE(resolveThreadCount(8) == 8);
}

TEST_CASE("thread cap 1: every share on the calling thread, no worker", "[common][threads]") {
  const std::thread::id caller = std::this_thread::get_id();
  const size_t workerPartsBefore = worker_pool::partsRunByWorkers();
  std::mutex seenMutex;
  std::set<std::thread::id> seen;
  std::atomic<int> shares{0};
  const auto record = [&] {
    std::lock_guard<std::mutex> lock(seenMutex);
    seen.insert(std::this_thread::get_id());
  };
  {
    const ScopedThreadCap cap(1);
    parallelFor(10000, 0, [&](size_t, size_t) { ++shares, record(); });
    parallelFor(10000, 8, [&](size_t, size_t) { ++shares, record(); });
    parallelForChunks(10000, 10, 8, [&](size_t, size_t) { record(); });
    // A caller that counted its parts itself: all run, each once, on this thread. Each part
    // takes 2 ms, time enough for an idle worker to take one were it offered.
    std::vector<std::atomic<int>> visits(7);
    parallelParts(7, [&](unsigned part) {
      ++visits[part], record();
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    });
    for (auto& v : visits) REQUIRE(v == 1);
  }
  REQUIRE(shares == 2);
  REQUIRE(seen == std::set<std::thread::id>{caller});
  REQUIRE(worker_pool::partsRunByWorkers() == workerPartsBefore);
}

TEST_CASE("thread cap 2: a part run by a worker keeps the cap for its nested loops",
          "[common][threads]") {
  const std::thread::id caller = std::this_thread::get_id();
  const bool workersExist = std::thread::hardware_concurrency() > 1;
  bool workerRanAPart = false;
  // A worker takes part 1 while part 0 waits a little for it; a few tries on a loaded machine.
  for (int attempt = 0; attempt < 20 && !workerRanAPart && workersExist; ++attempt) {
    std::atomic<bool> partOneStarted{false};
    std::atomic<bool> partOneOnWorker{false};
    std::atomic<unsigned> capOnWorker{0};
    // What each part's nested loop saw, checked after the join (Catch2 asserts on one thread).
    std::mutex nestedMutex;
    std::vector<size_t> nestedShares, nestedThreads;
    {
      const ScopedThreadCap cap(2);
      parallelParts(2, [&](unsigned part) {
        if (part == 0) {
          const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(200);
          while (!partOneStarted && std::chrono::steady_clock::now() < until)
            std::this_thread::yield();
        } else {
          partOneStarted = true;
          if (std::this_thread::get_id() != caller) {
            partOneOnWorker = true;
            capOnWorker = threadCap();
          }
        }
        // Asks for 8 threads: the cap, not the request nor the hardware, must bound it.
        std::mutex idsMutex;
        std::set<std::thread::id> ids;
        size_t shares = 0;
        parallelFor(1000, 8, [&](size_t, size_t) {
          std::lock_guard<std::mutex> lock(idsMutex);
          ++shares;
          ids.insert(std::this_thread::get_id());
        });
        std::lock_guard<std::mutex> lock(nestedMutex);
        nestedShares.push_back(shares);
        nestedThreads.push_back(ids.size());
      });
    }
    REQUIRE(nestedShares == std::vector<size_t>{2, 2});
    for (size_t threads : nestedThreads) REQUIRE(threads <= 2);
    if (partOneOnWorker) {
      workerRanAPart = true;
      REQUIRE(capOnWorker == 2);
    }
    REQUIRE(threadCap() == 0);
  }
  // With more than one hardware thread, a worker must have taken part 1 at least once, or the
  // test proved nothing about workers.
  if (workersExist) REQUIRE(workerRanAPart);
}
