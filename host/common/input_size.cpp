#include "common/input_size.h"

#include <atomic>

#include "common/memory_budget.h"

namespace tessera {
namespace {

std::atomic<uint64_t> maxInput{kDefaultMaxInputBytes};

}  // namespace

uint64_t maxInputBytes() { return maxInput.load(); }
void setMaxInputBytes(uint64_t bytes) { maxInput.store(bytes); }

void requireInputWithinLimit(uint64_t bytes, const std::string& name) {
  if (bytes <= maxInputBytes()) return;
  throw MemoryLimitError(name + ": the input is larger than the input-size limit of " +
                         formatByteSize(maxInputBytes()) +
                         " (an endless device such as /dev/zero? raise the limit with "
                         "--max-input-size SIZE)");
}

}  // namespace tessera
