#include "common/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <numeric>
#include <thread>

#include "common/thread_cap.h"
#include "common/worker_pool.h"

namespace tessera {

unsigned resolveThreadCount(unsigned requested) {
  const unsigned cap = threadCap();
  const unsigned threads =
      requested ? requested : std::max(1u, std::thread::hardware_concurrency());
  return cap != 0 && cap < threads ? cap : threads;
}

void parallelParts(unsigned parts, const std::function<void(unsigned part)>& body) {
  const unsigned cap = threadCap();
  std::mutex firstErrorMutex;
  std::exception_ptr firstError;
  // A thrown exception must not leave a thread (std::terminate) or cut the others short.
  auto guarded = [&](unsigned part) {
    try {
      if (cap == 0) {
        body(part);
      } else {
        // The caller's cap goes with the part to the worker that runs it (thread_cap.h).
        ScopedThreadCap callersCap(cap);
        body(part);
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(firstErrorMutex);
      if (!firstError) firstError = std::current_exception();
    }
  };
  if (cap != 0 && parts > cap) {
    // More parts than the cap allows threads (a caller that counted its parts itself): `cap`
    // lanes, lane k running parts k, k + cap, … in turn. Parts never wait for each other, so
    // running some one after another is allowed; with cap 1 every part stays on this thread.
    worker_pool::runParts(cap, [&](unsigned lane) {
      for (unsigned part = lane; part < parts; part += cap) guarded(part);
    });
  } else {
    worker_pool::runParts(parts, guarded);
  }
  if (firstError) std::rethrow_exception(firstError);
}

void parallelFor(size_t count, unsigned threads,
                 const std::function<void(size_t begin, size_t end)>& body) {
  if (count == 0) return;
  const size_t shares = std::min<size_t>(resolveThreadCount(threads), count);
  parallelParts(unsigned(shares),
                [&](unsigned part) { body(count * part / shares, count * (part + 1) / shares); });
}

void parallelForChunks(size_t count, size_t chunk, unsigned threads,
                       const std::function<void(size_t begin, size_t end)>& body) {
  if (count == 0) return;
  chunk = std::max<size_t>(chunk, 1);
  std::atomic<size_t> next{0};
  parallelParts(unsigned(std::min<size_t>(resolveThreadCount(threads), count)), [&](unsigned) {
    for (size_t begin = next.fetch_add(chunk); begin < count; begin = next.fetch_add(chunk))
      body(begin, std::min(count, begin + chunk));
  });
}

unsigned threadsForChunks(size_t count, size_t chunk, unsigned threads) {
  return count >= kTurnsForSecondThread * std::max<size_t>(chunk, 1) ? threads : 1u;
}

void parallelForLargestFirst(const std::vector<double>& estimates, unsigned threads,
                             const std::function<void(size_t index)>& body) {
  std::vector<size_t> order(estimates.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return estimates[a] > estimates[b]; });
  parallelForChunks(order.size(), 1, threads, [&](size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k) body(order[k]);
  });
}

}  // namespace tessera
