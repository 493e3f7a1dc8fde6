// The temporary files atomic writes have open (host/io/atomic_file.h), kept where a signal
// handler can reach them: on SIGINT or SIGTERM (Ctrl-C, kill) they are removed before the
// process dies, so an interrupted write leaves no ".name.tmp-<pid>-<n>" behind.
//
// The table is fixed-size (kMaxPendingTempFiles paths of up to kMaxPendingTempPath bytes) and
// lock-free: a handler may only call async-signal-safe functions (unlink, signal, raise), so it
// can neither allocate nor take a lock. A path that does not fit, or a table that is full, is
// simply not tracked (the write itself goes on; only the cleanup on a signal is lost).
#pragma once
#include <cstddef>

namespace tessera {

constexpr size_t kMaxPendingTempFiles = 32;
constexpr size_t kMaxPendingTempPath = 4096;  // PATH_MAX on Linux, with its NUL

// Records `path` (NUL-terminated) as a temporary file to remove on a signal; returns its slot,
// or -1 when it is not tracked. Thread-safe.
int registerPendingTempFile(const char* path);
// Forgets the slot registerPendingTempFile returned (after the rename or the unlink); -1 is
// ignored. Thread-safe.
void forgetPendingTempFile(int slot);

// Installs handlers for SIGINT and SIGTERM that unlink every pending temporary file, restore
// the default action and raise the signal again (so the exit status still says "killed by
// SIGINT"). A signal that is ignored when this is called (nohup, a shell's background job)
// stays ignored. Call once, early in main(); a library user keeps their own handlers by not
// calling it.
void removePendingTempFilesOnSignals();

}  // namespace tessera
