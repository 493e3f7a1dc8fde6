// The process's worker threads, kept between parallel calls: starting a thread per share at
// every call (a clone, a stack, a join) cost more than small shares took, and a join waited
// for a thread the scheduler had not yet run. parallel_for.h is the interface.
#pragma once

#include <cstddef>
#include <functional>

namespace tessera::worker_pool {

// Runs body(part) for part 0 … parts − 1: part 0 on the calling thread, the others on idle
// workers or, if none has taken one by the time the caller is free, on the caller too. So
// parts may run one after another: they must not wait for each other. Returns when all have
// finished. body must not throw (parallelParts catches for it).
void runParts(unsigned parts, const std::function<void(unsigned part)>& body);

// Parts run by the workers (not by the callers) since the process started, for the tests that
// check a call under a thread cap of 1 (thread_cap.h) never left its thread.
size_t partsRunByWorkers();

}  // namespace tessera::worker_pool
