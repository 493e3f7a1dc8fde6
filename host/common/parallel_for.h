// The one thread fan-out: a range of independent items split into even contiguous shares, one
// per thread, the calling thread taking the first share.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace tessera {

// Threads to use for `requested`: requested itself, or all hardware threads (at least 1) when 0;
// at most the thread cap in force (thread_cap.h).
unsigned resolveThreadCount(unsigned requested);

// Runs body(part) for part 0 … parts − 1, part 0 on the calling thread, the others on the
// process's kept worker threads (worker_pool.h) or, when none is free, on the calling thread
// after its own: parts must not wait for each other. Returns after every part has finished;
// the first exception any part threw is then rethrown here. Under a thread cap (thread_cap.h)
// each part runs under it wherever it runs, and at most `cap` threads share the parts.
void parallelParts(unsigned parts, const std::function<void(unsigned part)>& body);

// Splits [0, count) into min(threads, count) shares [count·k/n, count·(k+1)/n) and runs
// body(begin, end) on each through parallelParts (threads 0: all hardware threads). Nothing
// runs for count 0. Items must be independent: which thread gets which share is not fixed
// beyond that rule, so results must not depend on the split.
void parallelFor(size_t count, unsigned threads,
                 const std::function<void(size_t begin, size_t end)>& body);

// The same for items whose costs differ: min(threads, count) threads take chunks [begin, end)
// of `chunk` items (the last one shorter) in turn from a shared counter, so no thread waits
// long for the slowest share. Every index is in exactly one chunk.
void parallelForChunks(size_t count, size_t chunk, unsigned threads,
                       const std::function<void(size_t begin, size_t end)>& body);

// The threads for parallelForChunks over `count` items taken `chunk` at a time when each item
// is cheap: `threads` from kTurnsForSecondThread chunks on, else 1. A shorter loop's hand-out
// and join cost about what a second thread saves on 2 cores, and more on a loaded machine,
// where the join waits for a worker preempted in its part (bench/HISTORY.md, "CAD path: where
// the two cores idle").
constexpr size_t kTurnsForSecondThread = 8;
unsigned threadsForChunks(size_t count, size_t chunk, unsigned threads);

// The same, one item at a time, for items whose costs can be estimated before the work: handed
// out largest estimate first (ties in index order), so that no large item starts last while the
// other threads have nothing left (the longest-processing-time-first rule). Runs body(i) for
// every i in [0, estimates.size()); the order of the calls is not the order of the indices.
void parallelForLargestFirst(const std::vector<double>& estimates, unsigned threads,
                             const std::function<void(size_t index)>& body);

}  // namespace tessera
