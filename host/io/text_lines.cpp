#include "io/text_lines.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <system_error>

namespace tessera {
namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

}  // namespace

std::ifstream openForReading(const std::string& path, const char* kindOfFile) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(InputErrorKind::Io, path, 0, std::string("is a directory, not ") + kindOfFile);
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int err = errno;
    std::string reason = "cannot open for reading";
    if (err != 0) reason += ": " + std::generic_category().message(err);
    throw InputError(InputErrorKind::Io, path, 0, reason);
  }
  return in;
}

std::string readWhole(std::istream& in, const std::string& nameForMessages, bool stopAfterNul) {
  // In blocks, not a character at a time: a gigabyte in a second, not in twenty.
  std::string text;
  char block[1 << 16];
  while (in.read(block, sizeof block) || in.gcount() > 0) {
    const size_t n = size_t(in.gcount());
    text.append(block, n);
    if (stopAfterNul && std::memchr(block, '\0', n) != nullptr) break;
  }
  if (in.bad()) throw InputError(InputErrorKind::Io, nameForMessages, 0, "read error");
  return text;
}

TextLines::TextLines(std::istream& in, std::string nameForMessages)
    : in_(in), name_(std::move(nameForMessages)) {}

// std::getline into chunk_ in blocks, refusing a line longer than kMaxTextLineBytes before it
// is all in memory: bytes without a newline (/dev/zero) stop after a megabyte.
bool TextLines::readChunk() {
  chunk_.clear();
  char block[1 << 14];
  for (;;) {
    in_.getline(block, sizeof block);
    const size_t n = size_t(in_.gcount());
    // Three ways out of getline: the end of the input (the last line, without a newline, or
    // nothing left); the newline, which gcount() counted; or a full block, the line going on.
    const bool atEnd = in_.eof(), atNewline = !atEnd && !in_.fail();
    if (!atEnd && !atNewline && (in_.bad() || n == 0)) return false;
    chunk_.append(block, atNewline ? n - 1 : n);
    if (chunk_.size() > kMaxTextLineBytes)
      fail(InputErrorKind::Syntax, linesRead_ + 1,
           "a line longer than " + std::to_string(kMaxTextLineBytes >> 20) +
               " MiB (is this a text file?)");
    if (atEnd) return !chunk_.empty();
    if (atNewline) return true;
    in_.clear();
  }
}

bool TextLines::nextPhysicalLine(std::string_view& line) {
  if (chunkPos_ > chunk_.size()) {
    if (!readChunk()) return false;
    chunkPos_ = 0;
    // A UTF-8 byte order mark (Windows editors write one) is no content.
    if (linesRead_ == 0 && chunk_.compare(0, kUtf8Bom.size(), kUtf8Bom) == 0)
      chunkPos_ = kUtf8Bom.size();
  }
  ++linesRead_;
  // A CR ends a line too (classic Mac files), unless it is the CR of a CRLF: then getline
  // left it last in the chunk and it is a blank like any other.
  const size_t cr = chunk_.find('\r', chunkPos_);
  if (cr == std::string::npos || cr + 1 == chunk_.size()) {
    line = std::string_view(chunk_).substr(chunkPos_);
    chunkPos_ = std::string::npos;
  } else {
    line = std::string_view(chunk_).substr(chunkPos_, cr - chunkPos_);
    chunkPos_ = cr + 1;
  }
  return true;
}

bool TextLines::next() {
  std::string_view rest;
  while (nextPhysicalLine(rest)) {
    tokens_.clear();
    size_t k = 0;
    while (k < rest.size()) {
      while (k < rest.size() && isBlank(rest[k])) ++k;
      const size_t start = k;
      while (k < rest.size() && !isBlank(rest[k])) ++k;
      if (k > start) tokens_.push_back(rest.substr(start, k - start));
    }
    if (!tokens_.empty() && tokens_.front().front() != '#') return true;
  }
  // getline sets failbit at a clean end of file too; only badbit means the read broke.
  if (in_.bad()) fail(InputErrorKind::Io, linesRead_ + 1, "read error");
  tokens_.clear();
  return false;
}

void TextLines::fail(InputErrorKind kind, int line, const std::string& reason) const {
  throw InputError(kind, name_, line, reason);
}

void TextLines::fail(InputErrorKind kind, const std::string& reason) const {
  fail(kind, linesRead_, reason);
}

std::string_view withoutPlus(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '+' && token[1] != '-')
    token.remove_prefix(1);
  return token;
}

std::string commentHint(const std::vector<std::string_view>& tokens) {
  for (std::string_view t : tokens)
    if (t.front() == '#') return " ('#' starts a comment only at the beginning of a line)";
  return "";
}

// std::from_chars is locale-independent, unlike strtod and streams.
double parseCoordinate(const TextLines& lines, std::string_view token, const std::string& what) {
  const std::string_view number = withoutPlus(token);
  double value = 0;
  const auto [ptr, ec] = std::from_chars(number.data(), number.data() + number.size(), value,
                                         std::chars_format::general);
  if (ptr != number.data() + number.size() ||
      (ec != std::errc() && ec != std::errc::result_out_of_range))
    lines.fail(InputErrorKind::Syntax, quotedToken(token) + " is not a number (" + what + ")");
  if (ec == std::errc::result_out_of_range)
    lines.fail(InputErrorKind::Range,
               quotedToken(token) + " is outside the range of a double (" + what + ")");
  if (!std::isfinite(value))
    lines.fail(InputErrorKind::NonFinite,
               quotedToken(token) + " is not a finite number (" + what + ")");
  if (std::fabs(value) > kMaxAbsInputCoordinate)
    lines.fail(InputErrorKind::Range, quotedToken(token) +
                                          " exceeds the largest accepted magnitude 1e15 (" +
                                          what + ")");
  return value;
}

bool parseInteger(std::string_view token, long long& value, bool& outOfRange) {
  const char* first = token.data();
  const char* last = first + token.size();
  const auto [ptr, ec] = std::from_chars(first, last, value);
  outOfRange = ec == std::errc::result_out_of_range;
  return (ec == std::errc() || outOfRange) && ptr == last && first != last;
}

}  // namespace tessera
