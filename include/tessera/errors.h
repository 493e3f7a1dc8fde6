// Tessera's exceptions: one base, tessera::Error, and a type per cause, so a caller can catch
// what it can handle (a bad file) apart from what it cannot (a lost device). Part of the public
// API (include/tessera/); the library's readers throw InputError directly.
#pragma once
#include <stdexcept>
#include <string>

namespace tessera {

// Every error the public API throws derives from this (and so from std::runtime_error).
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What was wrong with an input file, independent of the message text. Append new kinds at the
// end: callers compare against the names, never the numeric values.
enum class InputErrorKind {
  Io,         // the file could not be opened, read, written or renamed
  Syntax,     // a token or line does not have the expected shape
  Count,      // fewer or more items than declared (a truncated file, a wrong header count)
  NonFinite,  // NaN or infinity where a finite number is required
  Range,      // a finite number outside the accepted magnitude
  Degree,     // a polynomial degree outside 1..7
  Topology,   // indices or connectivity that do not form a valid mesh/net
  Weight,     // a rational weight that is negative or otherwise unusable
  Knots,      // a knot vector that is not non-decreasing or has the wrong length
};

inline const char* inputErrorKindName(InputErrorKind kind) {
  switch (kind) {
    case InputErrorKind::Io: return "Io";
    case InputErrorKind::Syntax: return "Syntax";
    case InputErrorKind::Count: return "Count";
    case InputErrorKind::NonFinite: return "NonFinite";
    case InputErrorKind::Range: return "Range";
    case InputErrorKind::Degree: return "Degree";
    case InputErrorKind::Topology: return "Topology";
    case InputErrorKind::Weight: return "Weight";
    case InputErrorKind::Knots: return "Knots";
  }
  return "Unknown";
}

// A bad input file or failed file I/O. what() reads "<file>:<line>: <reason>", the form
// compilers use, so editors and terminals can jump to the spot. Lines are 1-based; line 0
// means "no particular line" (the file could not be opened) and is left out: "<file>: <reason>".
class InputError : public Error {
 public:
  InputError(InputErrorKind kind, const std::string& file, int line, const std::string& reason)
      : Error(format(file, line, reason)), kind_(kind), file_(file), line_(line), reason_(reason) {}

  InputErrorKind kind() const { return kind_; }
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& reason() const { return reason_; }

 private:
  static std::string format(const std::string& file, int line, const std::string& reason) {
    std::string where = file;
    if (line > 0) where += ":" + std::to_string(line);
    return where + ": " + reason;
  }

  InputErrorKind kind_;
  std::string file_;
  int line_;
  std::string reason_;
};

// Patches or options handed in by code that Tessera cannot take: a wrong control-point count,
// a degree outside 1..7, a negative weight, a threshold out of range. The message names the
// patch or option.
class ArgumentError : public Error {
 public:
  using Error::Error;
};

// The work would exceed a limit: the quad-tree's node budget (names the patch and level).
class LimitError : public Error {
 public:
  using Error::Error;
};

// No usable Vulkan device where one was required, or the device failed during the work
// (lost, out of memory). Device::Auto falls back to the CPU instead of throwing this.
class DeviceError : public Error {
 public:
  using Error::Error;
};

}  // namespace tessera
