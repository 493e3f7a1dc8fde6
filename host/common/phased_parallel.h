// Several parallel loops that follow one another, each with a serial step after it, run in one
// fan-out: the worker threads are woken once for all of them, not once per loop. A loop of
// parallelForChunks wakes a sleeping worker (35–40 µs on an idle 2-core machine, 120–370 µs
// under load, bench/HISTORY.md "CAD path: where the two cores idle"), which a loop of a few
// hundred microseconds, like each of the CAD import's three, pays every time.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace tessera {

struct ParallelPhase {
  // The phase's item count, asked when the phase opens (after the phase before has ended and
  // its `then` has run, which may decide it).
  std::function<size_t()> count;
  size_t chunk = 1;  // items handed out together
  std::function<void(size_t item)> item;
  // The serial step after every item of the phase has finished, on one thread; may be empty.
  std::function<void()> then;
};

// Runs the phases in order on `threads` threads (0: all cores). Items of a phase run on any
// thread, in chunks taken in turn; no item of a phase starts before the phase before has ended
// (every item finished, its `then` returned). Where items threw, the lowest item's exception is
// rethrown and no later step runs, as in a loop in order; so is an exception of a `then`.
// A thread with nothing to take waits for a phase to end by yielding for ~250 µs (a sleeper's
// wake-up is what this saves), then sleeping; it only ever waits for work another thread is doing,
// so the phases also run to the end on the calling thread alone when no worker is free.
void runPhases(const std::vector<ParallelPhase>& phases, unsigned threads);

}  // namespace tessera
