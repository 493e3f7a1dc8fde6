#include "io/input_limit.h"

#include "io/errors.h"

namespace tessera {

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
