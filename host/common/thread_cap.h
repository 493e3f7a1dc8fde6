// A limit on the CPU threads of one call, for programs that run Tessera inside their own job
// systems (TessellatorOptions::threads, the CLI's --threads). It is set for a scope on the
// calling thread, and parallelParts carries it onto the workers that run the scope's parts, so
// loops nested in those parts obey it too. resolveThreadCount (parallel_for.h) applies it.
#pragma once

namespace tessera {

// The cap in force on this thread; 0: none.
unsigned threadCap();

// Whether this call may hand work to a helper thread of its own (a pipeline built in the
// background, the CLI's context made or released aside): not under a cap of 1, whose promise
// is that nothing runs off the calling thread.
inline bool helperThreadsAllowed() { return threadCap() != 1; }

// Caps the threads of every parallel loop run in its scope on this thread at `cap` (each loop
// uses at most `cap` threads, the calling one included): cap 1 runs every part on the calling
// thread and starts no worker. cap 0 adds no cap, and a scope never lifts an enclosing one: the
// smaller non-zero of the two holds. The previous cap is back when the scope ends.
class ScopedThreadCap {
 public:
  explicit ScopedThreadCap(unsigned cap);
  ~ScopedThreadCap();
  ScopedThreadCap(const ScopedThreadCap&) = delete;
  ScopedThreadCap& operator=(const ScopedThreadCap&) = delete;

 private:
  unsigned previous_;
};

}  // namespace tessera
