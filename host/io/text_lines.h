// Building blocks for the line-oriented and whole-file readers added after .bpt and .grid
// (OBJ meshes, JSON scenes): opening a file with a clear Io error, reading it whole, data lines
// split into tokens with their 1-based line numbers, and locale-independent number parsing
// with the strictness of the .bpt reader (finite, |value| ≤ 1e15, no hex floats).
// The .bpt and .grid readers keep their own copies of the line splitter on purpose (they
// predate this header); the rules are the same.
#pragma once
#include <fstream>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

#include "io/errors.h"
#include "io/quoted_token.h"  // quotedToken for the readers

namespace tessera {

// Largest accepted |coordinate| in any input file, as in .bpt and .grid: squared lengths and
// bounding-box diagonals computed later stay far from overflow.
constexpr double kMaxAbsInputCoordinate = 1e15;

// The longest physical line the text readers take (TextLines): longer is a Syntax error.
constexpr size_t kMaxTextLineBytes = size_t(1) << 20;


// Opens `path` for reading in binary mode (CRLF is handled by the parsers). A directory or an
// unopenable file is an InputError of kind Io; `kindOfFile` completes "is a directory, not
// <kindOfFile>", e.g. "an OBJ file".
std::ifstream openForReading(const std::string& path, const char* kindOfFile);

// All of `in` as one string; a read error (badbit) is an InputError of kind Io. With
// `stopAfterNul`, reading stops at the end of the 64 KiB block holding the first NUL byte: for
// formats whose text can hold no NUL (JSON), the parser's error is then the same, at or
// before that byte, and /dev/zero or binary garbage costs a block, not the input-size limit.
std::string readWhole(std::istream& in, const std::string& nameForMessages,
                      bool stopAfterNul = false);

// The UTF-8 byte order mark some editors put at the start of a text file.
constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

// The data lines of a text input, split at blanks (space, tab, CR, VT, FF) into tokens.
// Blank lines and lines whose first token begins with '#' are skipped. Lines end in LF, CRLF
// or a lone CR (old Mac files), and a UTF-8 byte order mark at the start is skipped.
class TextLines {
 public:
  TextLines(std::istream& in, std::string nameForMessages);

  // Advances to the next data line; false at the end of the input.
  bool next();
  // The tokens of the line next() last returned; they stay valid until the next call.
  const std::vector<std::string_view>& tokens() const { return tokens_; }
  // The 1-based number of the line next() last returned.
  int line() const { return linesRead_; }
  // Where more input was expected once next() has returned false: the line after the last.
  int lineAfterEnd() const { return linesRead_ + 1; }
  const std::string& name() const { return name_; }

  [[noreturn]] void fail(InputErrorKind kind, int line, const std::string& reason) const;
  [[noreturn]] void fail(InputErrorKind kind, const std::string& reason) const;

 private:
  std::istream& in_;
  std::string name_;
  // The next physical line (LF, CRLF or CR ended), 1-based numbering kept in linesRead_.
  bool nextPhysicalLine(std::string_view& line);
  bool readChunk();

  std::string chunk_;                   // what getline read up to the next LF
  size_t chunkPos_ = std::string::npos;  // where in chunk_ the next line starts; npos: read more
  std::vector<std::string_view> tokens_;
  int linesRead_ = 0;
};

// `token` without one leading '+' (other writers emit it; std::from_chars rejects it), unless a
// sign follows: "+-1" and "++1" stay invalid.
std::string_view withoutPlus(std::string_view token);

// For a line with the wrong number of tokens: a '#' inside it is the likely cause, since '#'
// starts a comment only at the beginning of a line. Empty when no token starts with '#'.
std::string commentHint(const std::vector<std::string_view>& tokens);

// `token` as a coordinate on the current line of `lines`: Syntax unless the whole token is a
// decimal number (an optional leading '+' is accepted, "+-1" and hex floats are not); Range
// when it overflows a double or exceeds kMaxAbsInputCoordinate; NonFinite for nan/inf.
// `what` ends the message in parentheses, e.g. "y of vertex 3".
double parseCoordinate(const TextLines& lines, std::string_view token, const std::string& what);

// True when the whole of `token` is a decimal integer (optional '-'; no '+'). `outOfRange` is
// set when it is one but does not fit a long long (value is then unspecified).
bool parseInteger(std::string_view token, long long& value, bool& outOfRange);

}  // namespace tessera
