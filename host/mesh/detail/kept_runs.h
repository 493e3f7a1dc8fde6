// The leaf runs' arrays (LeafRun), kept by the calling thread from one triangulateLeaves call
// to the next: their room only, never their contents (each run is cleared before it is
// walked). New ones every call were about half of rule T's page faults at δ 10⁻³ on the tea
// set (~250 of ~480 a run): malloc hands the last call's pages back to the system when they
// are freed, and the walk's writes faulted them in again.
#pragma once
#include <vector>

#include "mesh/detail/leaf_walk.h"

namespace tessera::triangulate_detail {

class KeptRuns {
 public:
  // Kept up to this much room in all (the tea set at 10⁻³ reserves ~6 MiB); a larger mesh's
  // runs are freed after the call.
  static constexpr size_t kKeptBytes = size_t(8) << 20;

  // `count` empty runs.
  std::vector<LeafRun>& take(size_t count) {
    runs_.resize(count);
    for (LeafRun& run : runs_) run.clear();
    return runs_;
  }

  // Calls release() when the call ends, by its return or by an exception (a memory limit, a
  // bad patch): a huge mesh's runs are not kept whichever way its call ended.
  struct ReleaseAtEnd {
    KeptRuns& kept;
    ~ReleaseAtEnd() { kept.release(); }
  };

  // After the call: the runs freed if they hold more than kKeptBytes.
  void release() {
    size_t bytes = 0;
    for (const LeafRun& run : runs_) bytes += run.capacityBytes();
    if (bytes > kKeptBytes) std::vector<LeafRun>().swap(runs_);
  }

 private:
  std::vector<LeafRun> runs_;
};

}  // namespace tessera::triangulate_detail
