// The largest input file a reader takes (--max-input-size; 1 GiB by default). A reader reads
// through a BoundedInput, which stops at the limit with a MemoryLimitError (CLI exit 4) naming
// the file, the limit and the option: /dev/zero or /dev/urandom behind a name like x.bpt then
// costs at most the limit, never memory without end. Text readers also refuse a line longer
// than kMaxTextLineBytes first (an InputError, exit 2), so endless bytes without a newline stop
// after a megabyte.
#pragma once
#include <cstdint>
#include <istream>
#include <streambuf>
#include <string>

#include "common/input_size.h"  // maxInputBytes, requireInputWithinLimit

namespace tessera {

// A stream over `source`'s buffer that throws (through the stream, which then has badbit set)
// once more than maxInputBytes() have been taken from it.
class BoundedInput {
 public:
  BoundedInput(std::istream& source, std::string nameForMessages);
  std::istream& stream() { return stream_; }

 private:
  class Buffer : public std::streambuf {
   public:
    Buffer(std::streambuf* source, std::string name) : source_(source), name_(std::move(name)) {}

   protected:
    int_type underflow() override;

   private:
    std::streambuf* source_;
    std::string name_;
    uint64_t taken_ = 0;
    char block_[1 << 16];
  };
  Buffer buffer_;
  std::istream stream_;
};

}  // namespace tessera
