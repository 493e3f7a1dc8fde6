// The shared helpers in host/common/: parallelFor and parallelForChunks hand out every index
// exactly once, parallelFor reports a worker's exception in the caller; Stopwatch never reads
// negative or backwards.
#include <catch2/catch.hpp>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include "common/parallel_for.h"
#include "common/stopwatch.h"

using namespace tessera;

TEST_CASE("parallelFor covers every index exactly once", "[common]") {
  for (size_t count : {size_t(0), size_t(1), size_t(7), size_t(1000)}) {
    for (unsigned threads = 1; threads <= 8; ++threads) {
      std::vector<std::atomic<int>> visits(count);
      std::atomic<int> calls{0};
      parallelFor(count, threads, [&](size_t begin, size_t end) {
        ++calls;
        CHECK(begin < end);
        for (size_t i = begin; i < end; ++i) ++visits[i];
      });
      INFO("count " << count << ", threads " << threads);
      for (size_t i = 0; i < count; ++i) REQUIRE(visits[i] == 1);
      // One share per thread, never more shares than items, none for an empty range.
      CHECK(calls == int(std::min<size_t>(threads, count)));
    }
  }
}

TEST_CASE("parallelForChunks covers every index exactly once, in chunks", "[common]") {
  for (size_t count : {size_t(0), size_t(1), size_t(7), size_t(1000)}) {
    for (size_t chunk : {size_t(0), size_t(1), size_t(16), size_t(5000)}) {
      for (unsigned threads : {1u, 2u, 5u}) {
        std::vector<std::atomic<int>> visits(count);
        std::atomic<size_t> calls{0};
        parallelForChunks(count, chunk, threads, [&](size_t begin, size_t end) {
          ++calls;
          CHECK(begin < end);
          CHECK(end - begin <= std::max<size_t>(chunk, 1));
          CHECK((begin % std::max<size_t>(chunk, 1)) == 0);
          for (size_t i = begin; i < end; ++i) ++visits[i];
        });
        INFO("count " << count << ", chunk " << chunk << ", threads " << threads);
        for (size_t i = 0; i < count; ++i) REQUIRE(visits[i] == 1);
        const size_t step = std::max<size_t>(chunk, 1);
        CHECK(calls == (count + step - 1) / step);
      }
    }
  }
}

TEST_CASE("parallelForLargestFirst covers every index once, largest estimate first", "[common]") {
  const std::vector<double> estimates = {3, 9, 1, 9, 0, 5, 3};
  for (unsigned threads : {1u, 2u, 5u}) {
    std::vector<std::atomic<int>> visits(estimates.size());
    parallelForLargestFirst(estimates, threads, [&](size_t i) { ++visits[i]; });
    INFO("threads " << threads);
    for (size_t i = 0; i < estimates.size(); ++i) REQUIRE(visits[i] == 1);
  }
  // On one thread the calls come in the hand-out order: decreasing estimate, ties by index.
  std::vector<size_t> order;
  parallelForLargestFirst(estimates, 1, [&](size_t i) { order.push_back(i); });
  CHECK(order == std::vector<size_t>{1, 3, 5, 0, 6, 2, 4});
  parallelForLargestFirst({}, 2, [&](size_t) { FAIL("no items, no calls"); });
}

TEST_CASE("threadsForChunks gives a second thread only from kTurnsForSecondThread chunks on",
          "[common]") {
  CHECK(threadsForChunks(8 * 64 - 1, 64, 4) == 1u);
  CHECK(threadsForChunks(8 * 64, 64, 4) == 4u);
  CHECK(threadsForChunks(7, 0, 0) == 1u);  // a chunk of 0 is taken as 1, as parallelForChunks does
  CHECK(threadsForChunks(8, 0, 0) == 0u);  // 0: every hardware thread
}

TEST_CASE("parallelFor with 0 threads uses every hardware thread", "[common]") {
  CHECK(resolveThreadCount(0) == std::max(1u, std::thread::hardware_concurrency()));
  CHECK(resolveThreadCount(3) == 3u);
  std::vector<std::atomic<int>> visits(100);
  parallelFor(visits.size(), 0, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) ++visits[i];
  });
  for (auto& v : visits) REQUIRE(v == 1);
}

TEST_CASE("parallelFor rethrows a worker's exception after all shares finish", "[common]") {
  for (unsigned threads : {1u, 4u}) {
    std::atomic<int> finished{0};
    auto failLast = [&](size_t begin, size_t end) {
      if (end == 100) throw std::runtime_error("share ending at 100 failed");
      (void)begin;
      ++finished;
    };
    CHECK_THROWS_WITH(parallelFor(100, threads, failLast), "share ending at 100 failed");
    // The other shares still ran to completion before the exception reached the caller.
    CHECK(finished == int(threads) - 1);
  }
}

TEST_CASE("Stopwatch is non-negative and monotonic", "[common]") {
  Stopwatch stopwatch;
  double previousMs = 0.0;
  for (int i = 0; i < 1000; ++i) {
    const double ms = stopwatch.elapsedMs();
    REQUIRE(ms >= previousMs);
    previousMs = ms;
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const double seconds = stopwatch.elapsedSeconds();
  CHECK(seconds >= 0.005);
  CHECK(stopwatch.elapsedMs() >= seconds * 1000.0);
  stopwatch.restart();
  CHECK(stopwatch.elapsedSeconds() >= 0.0);
  CHECK(stopwatch.elapsedSeconds() < seconds);
}
