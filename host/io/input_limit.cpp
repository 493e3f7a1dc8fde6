#include "io/input_limit.h"

#include <atomic>

#include "common/memory_budget.h"
#include "io/errors.h"

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

BoundedInput::BoundedInput(std::istream& source, std::string nameForMessages)
    : buffer_(source.rdbuf(), std::move(nameForMessages)), stream_(&buffer_) {
  // The limit's exception must leave the stream, not only set badbit.
  stream_.exceptions(std::ios::badbit);
}

BoundedInput::Buffer::int_type BoundedInput::Buffer::underflow() {
  if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
  std::streamsize got = 0;
  try {
    got = source_->sgetn(block_, sizeof block_);
  } catch (const std::exception& e) {
    throw InputError(InputErrorKind::Io, name_, 0, std::string("read error: ") + e.what());
  }
  if (got <= 0) return traits_type::eof();
  taken_ += uint64_t(got);
  requireInputWithinLimit(taken_, name_);
  setg(block_, block_, block_ + got);
  return traits_type::to_int_type(block_[0]);
}

}  // namespace tessera
