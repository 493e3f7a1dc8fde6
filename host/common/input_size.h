// The largest input file a reader takes (--max-input-size; 1 GiB by default), shared by the
// readers of host/io/ (through BoundedInput, io/input_limit.h) and host/cad/ (Open CASCADE
// reads by path: the file's size is checked first).
#pragma once
#include <cstdint>
#include <string>

namespace tessera {

constexpr uint64_t kDefaultMaxInputBytes = uint64_t(1) << 30;
uint64_t maxInputBytes();
void setMaxInputBytes(uint64_t bytes);

// Throws MemoryLimitError (common/memory_budget.h) naming `name` when `bytes` read so far (or
// a file's size) exceed maxInputBytes().
void requireInputWithinLimit(uint64_t bytes, const std::string& name);

}  // namespace tessera
