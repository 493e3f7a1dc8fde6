#include "common/thread_cap.h"

namespace tessera {
namespace {

thread_local unsigned currentCap = 0;  // 0: no cap

}  // namespace

unsigned threadCap() { return currentCap; }

ScopedThreadCap::ScopedThreadCap(unsigned cap) : previous_(currentCap) {
  if (cap != 0 && (previous_ == 0 || cap < previous_)) currentCap = cap;
}

ScopedThreadCap::~ScopedThreadCap() { currentCap = previous_; }

}  // namespace tessera
