#include "io/pending_temp_files.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstring>
#include <initializer_list>

namespace tessera {
namespace {

enum SlotState : int { kFree = 0, kFilling = 1, kPending = 2 };

struct Slot {
  std::atomic<int> state{kFree};
  char path[kMaxPendingTempPath];
};

Slot slots[kMaxPendingTempFiles];

// Lock-free atomics are async-signal-safe to read; a platform without them would need another
// design, so say so at compile time.
static_assert(std::atomic<int>::is_always_lock_free);

// C linkage, as a signal handler; static, so that no name of Tessera's reaches a program that
// links libtessera.a (extern "C" would otherwise make it global even in this namespace).
extern "C" {
static void unlinkPendingAndReraise(int signal) {
  for (Slot& slot : slots)
    if (slot.state.load(std::memory_order_acquire) == kPending) ::unlink(slot.path);
  ::signal(signal, SIG_DFL);
  ::raise(signal);
}
}

}  // namespace

int registerPendingTempFile(const char* path) {
  const size_t length = std::strlen(path);
  if (length >= kMaxPendingTempPath) return -1;
  for (size_t i = 0; i < kMaxPendingTempFiles; ++i) {
    int expected = kFree;
    if (slots[i].state.compare_exchange_strong(expected, kFilling, std::memory_order_acquire)) {
      std::memcpy(slots[i].path, path, length + 1);
      slots[i].state.store(kPending, std::memory_order_release);  // the handler may use it now
      return int(i);
    }
  }
  return -1;
}

void forgetPendingTempFile(int slot) {
  if (slot >= 0 && size_t(slot) < kMaxPendingTempFiles)
    slots[slot].state.store(kFree, std::memory_order_release);
}

void removePendingTempFilesOnSignals() {
  struct sigaction action {};
  action.sa_handler = unlinkPendingAndReraise;
  sigemptyset(&action.sa_mask);
  // Both signals blocked while the handler runs, so a second one cannot interrupt the unlinks.
  sigaddset(&action.sa_mask, SIGINT);
  sigaddset(&action.sa_mask, SIGTERM);
  action.sa_flags = SA_RESETHAND;
  for (const int signal : {SIGINT, SIGTERM}) {
    // A signal the parent ignores stays ignored (nohup, a shell's background job).
    struct sigaction previous {};
    if (::sigaction(signal, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN) continue;
    ::sigaction(signal, &action, nullptr);
  }
}

}  // namespace tessera
