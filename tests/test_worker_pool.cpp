// parallelParts on the kept worker threads (common/worker_pool.h): threads are not started
// anew at every call, nested and concurrent calls finish with every part run once, and more
// parts than threads all run.
#include <catch2/catch.hpp>

#include <atomic>
#include <thread>
#include <vector>

#include "common/parallel_for.h"

using namespace tessera;

namespace {

// Counts the threads that ever ran a part: a thread_local is constructed once per thread.
std::atomic<int> threadsSeen{0};
struct SeenOnce {
  SeenOnce() { ++threadsSeen; }
};
thread_local SeenOnce seenOnce;

}  // namespace

TEST_CASE("parallelParts keeps its threads between calls", "[common]") {
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  const int before = threadsSeen;
  for (int call = 0; call < 200; ++call) {
    std::atomic<int> ran{0};
    parallelParts(hardware + 1, [&](unsigned) {
      (void)&seenOnce;  // odr-use: constructs this thread's counter on first use
      ++ran;
    });
    REQUIRE(ran == int(hardware + 1));
  }
  // The caller and at most hardware − 1 workers; a thread per part and call would be ~200·hw.
  CHECK(threadsSeen - before <= int(hardware));
}

TEST_CASE("parallelParts nested in a part runs every inner part once", "[common]") {
  constexpr unsigned kOuter = 5, kInner = 7;
  std::vector<std::atomic<int>> visits(kOuter * kInner);
  parallelParts(kOuter, [&](unsigned outer) {
    parallelParts(kInner, [&](unsigned inner) { ++visits[outer * kInner + inner]; });
  });
  for (auto& v : visits) REQUIRE(v == 1);
}

TEST_CASE("parallelFor from several threads at once covers each range once", "[common]") {
  constexpr size_t kCount = 5000;
  std::vector<std::vector<std::atomic<int>>> visits(3);
  for (auto& v : visits) v = std::vector<std::atomic<int>>(kCount);
  std::vector<std::thread> callers;
  for (size_t c = 0; c < visits.size(); ++c)
    callers.emplace_back([&, c] {
      for (int round = 0; round < 20; ++round)
        parallelForChunks(kCount, 64, 0, [&](size_t begin, size_t end) {
          for (size_t i = begin; i < end; ++i) ++visits[c][i];
        });
    });
  for (std::thread& caller : callers) caller.join();
  for (auto& v : visits)
    for (auto& count : v) REQUIRE(count == 20);
}
