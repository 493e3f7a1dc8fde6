// The one exception type for bad input and failed file I/O. Every reader (.bpt now; JSON
// scenes, grid data and OBJ later) and the atomic writer throw it, so the CLI can print
// what() as-is and tests can check the kind, file and line separately from the wording.
#pragma once
#include <stdexcept>
#include <string>

namespace tessera {

// What went wrong, independent of the message text. Append new kinds at the end: tests and
// callers compare against the names, never the numeric values, but keeping the order stable
// keeps logs comparable across versions.
enum class InputErrorKind {
  Io,         // the file could not be opened, read, written or renamed
  Syntax,     // a token or line does not have the expected shape
  Count,      // fewer or more items than declared (a truncated file, a wrong header count)
  NonFinite,  // NaN or infinity where a finite number is required
  Range,      // a finite number outside the accepted magnitude
  Degree,     // a polynomial degree outside 1..kMaxDegree
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

// what() reads "<file>:<line>: <reason>", the form compilers use, so editors and terminals
// can jump to the spot. Line numbers are 1-based; line 0 means "no particular line" (the
// file could not be opened, a rename failed) and is left out: "<file>: <reason>".
class InputError : public std::runtime_error {
 public:
  InputError(InputErrorKind kind, const std::string& file, int line, const std::string& reason)
      : std::runtime_error(format(file, line, reason)),
        kind_(kind),
        file_(file),
        line_(line),
        reason_(reason) {}

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

}  // namespace tessera
