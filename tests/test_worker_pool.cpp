// parallelParts on the kept worker threads (common/worker_pool.h): threads are not started
// anew at every call, nested and concurrent calls finish with every part run once, more
// parts than threads all run, and a forked child computes and exits without the parent's.
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <vector>

#include "common/parallel_for.h"

#include <sys/wait.h>
#include <unistd.h>

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

// Returns once every worker the pool keeps has run a part, so none is still starting. A fork
// while a thread is inside the allocator leaves the child a lock no one will release: glibc's
// malloc guards against that, but clang 14's AddressSanitizer allocator does not, and a worker
// still in its thread start (which allocates) made the sanitizer run's child hang at exit.
namespace {

void settleWorkers() {
  const unsigned parts = std::max(1u, std::thread::hardware_concurrency());
  std::atomic<unsigned> started{0};
  parallelParts(parts, [&](unsigned) {
    ++started;
    // Parts must not wait for each other without bound (the caller may run them in turn):
    // wait at most 5 s for the others to be running at once.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (started < parts && std::chrono::steady_clock::now() < deadline)
      std::this_thread::yield();
  });
}

}  // namespace

TEST_CASE("parallelFor in a forked child runs on the child and exits cleanly", "[common]") {
  settleWorkers();       // the parent's workers exist and wait for work
  std::fflush(nullptr);  // nothing buffered twice
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    ::alarm(20);  // a hang fails the test instead of stalling it
    std::vector<std::atomic<int>> visits(1000);
    parallelForChunks(visits.size(), 16, 0, [&](size_t begin, size_t end) {
      for (size_t i = begin; i < end; ++i) ++visits[i];
    });
    bool once = true;
    for (auto& v : visits) once = once && v == 1;
    // _exit, not exit: the parent's exit handlers are not the child's to run. A Vulkan
    // context left by an earlier test in this process (the GPU tests' shared one) would be
    // destroyed there and wait for lavapipe's threads, which are not in the child: it hung
    // the child whenever a Vulkan test ran first in the same process.
    std::fflush(nullptr);
    ::_exit(once ? 0 : 1);
  }
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
}
