// The run's memory budget: one process-wide number of bytes that the big allocations of every
// stage (readers, B-spline to Bézier, the quad-tree's mesh, Loop levels, writers) are checked
// against before they are made, so that a job too large for the machine stops early with a
// LimitError (CLI exit 4) that names the estimate, the budget and --memory-budget, instead of
// dying in std::bad_alloc or the kernel's OOM killer after gigabytes. Estimates are bytes per
// element from the real structs (sizeof) times counts known before the work; docs/hardening.md
// lists them.
#pragma once
#include <cstdint>
#include <string>

#include "tessera/errors.h"

namespace tessera {

// A stage's estimate exceeds the memory budget (or its count overflows 64 bits).
class MemoryLimitError : public LimitError {
 public:
  using LimitError::LimitError;
};

// What the machine gives this process, in bytes; 0 where unknown or unlimited.
struct MachineMemory {
  uint64_t available = 0;     // MemAvailable in /proc/meminfo
  uint64_t cgroupLimit = 0;   // memory.max (cgroup v2) or memory.limit_in_bytes (v1)
  uint64_t addressSpace = 0;  // RLIMIT_AS (ulimit -v)
};
MachineMemory queryMachineMemory();

// Half of the smallest known limit of `machine` (4 GiB when none is known). Half, because an
// estimate counts one stage's main arrays, not what stays alive from the stage before (the
// parsed text beside the patches, the tree beside the mesh), a std::vector's growth by doubling,
// the allocator's slack, or the Vulkan driver's own mappings (which count under RLIMIT_AS).
uint64_t defaultMemoryBudget(const MachineMemory& machine);

// The budget in force: set by the CLI's --memory-budget, else defaultMemoryBudget() of this
// machine (queried once).
uint64_t memoryBudget();
void setMemoryBudget(uint64_t bytes);

// Throws MemoryLimitError when `bytes` exceeds memoryBudget(): "<what> needs about <bytes>
// (estimate), more than the memory budget of <budget> (raise it with --memory-budget SIZE)".
void requireWithinMemoryBudget(uint64_t bytes, const std::string& what);

// a × b and a + b, clamped to UINT64_MAX instead of wrapping: an estimate that overflows is
// simply too large.
uint64_t saturatingMultiply(uint64_t a, uint64_t b);
uint64_t saturatingAdd(uint64_t a, uint64_t b);

// "1048576", "512K", "512M", "4G", "1.5G", "1T" (binary units, an optional trailing B or iB,
// any case) as bytes; std::invalid_argument naming `text` for anything else, zero, or more than
// 2^63 bytes.
uint64_t parseByteSize(const std::string& text);

// `bytes` for messages: "512 MiB", "1.50 GiB", "873 bytes".
std::string formatByteSize(uint64_t bytes);

}  // namespace tessera
