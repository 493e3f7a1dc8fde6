// .grid parsing, line by line so every error can name its line. Format and rules:
// grid_reader.h.
#include "io/grid_reader.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <system_error>
#include <vector>

#include "io/errors.h"
#include "io/quoted_token.h"

namespace tessera {
namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// The data lines of the input (blank and '#' lines skipped), split into tokens, with their
// 1-based line numbers.
class DataLines {
 public:
  DataLines(std::istream& in, const std::string& name) : in_(in), name_(name) {}

  // Advances to the next data line; false at the end of the input.
  bool next() {
    while (std::getline(in_, text_)) {
      ++linesRead_;
      split();
      if (!tokens_.empty() && tokens_.front().front() != '#') return true;
    }
    // getline sets failbit at a clean end of file too; only badbit means the read broke.
    if (in_.bad()) fail(InputErrorKind::Io, linesRead_ + 1, "read error");
    tokens_.clear();
    return false;
  }

  const std::vector<std::string_view>& tokens() const { return tokens_; }
  int line() const { return linesRead_; }
  // Where more input was expected once next() has returned false.
  int lineAfterEnd() const { return linesRead_ + 1; }

  [[noreturn]] void fail(InputErrorKind kind, int line, const std::string& reason) const {
    throw InputError(kind, name_, line, reason);
  }
  [[noreturn]] void fail(InputErrorKind kind, const std::string& reason) const {
    fail(kind, linesRead_, reason);
  }

  // For a line with the wrong number of tokens: a '#' inside it is the likely cause.
  std::string commentHint() const {
    for (std::string_view t : tokens_)
      if (t.front() == '#') return " ('#' starts a comment only at the beginning of a line)";
    return "";
  }

 private:
  void split() {
    tokens_.clear();
    const std::string_view rest(text_);
    size_t k = 0;
    while (k < rest.size()) {
      while (k < rest.size() && isBlank(rest[k])) ++k;
      const size_t start = k;
      while (k < rest.size() && !isBlank(rest[k])) ++k;
      if (k > start) tokens_.push_back(rest.substr(start, k - start));
    }
  }

  std::istream& in_;
  const std::string& name_;
  std::string text_;
  std::vector<std::string_view> tokens_;
  int linesRead_ = 0;
};

// std::from_chars is locale-independent, unlike strtod and streams; it rejects a leading '+',
// which other writers emit, so one is skipped ("+-1" stays invalid).
std::string_view withoutPlus(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '+' && token[1] != '-')
    token.remove_prefix(1);
  return token;
}

int parseDimension(const DataLines& lines, std::string_view token, const char* what) {
  const std::string_view digits = withoutPlus(token);
  long long value = 0;
  const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  const bool outOfRange = ec == std::errc::result_out_of_range;
  if (ptr != digits.data() + digits.size() || (ec != std::errc() && !outOfRange))
    lines.fail(InputErrorKind::Syntax, quotedToken(token) + " is not an integer (" + what + ")");
  if (outOfRange || value > kGridMaxPoints)
    lines.fail(InputErrorKind::Range, std::string(what) + " " + quotedToken(token) + " is too large");
  if (value < 2)
    lines.fail(InputErrorKind::Count,
               std::string(what) + " must be at least 2, found " + std::to_string(value));
  return static_cast<int>(value);
}

double parseCoordinate(const DataLines& lines, std::string_view token, const std::string& what) {
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
    lines.fail(InputErrorKind::NonFinite, quotedToken(token) + " is not a finite number (" + what + ")");
  if (std::fabs(value) > kGridMaxAbsCoordinate)
    lines.fail(InputErrorKind::Range, quotedToken(token) +
                                          " exceeds the largest accepted magnitude 1e15 (" +
                                          what + ")");
  return value;
}

}  // namespace

GridData parseGrid(std::istream& in, const std::string& nameForMessages) {
  DataLines lines(in, nameForMessages);
  if (!lines.next())
    lines.fail(InputErrorKind::Count, lines.lineAfterEnd(),
               "empty file: expected the grid size \"rows cols\"");
  if (lines.tokens().size() != 2)
    lines.fail(InputErrorKind::Syntax, "expected the grid size \"rows cols\" (two integers), found " +
                                           std::to_string(lines.tokens().size()) + " tokens" +
                                           lines.commentHint());
  GridData grid;
  grid.rows = parseDimension(lines, lines.tokens()[0], "rows");
  grid.cols = parseDimension(lines, lines.tokens()[1], "cols");
  const long long count = static_cast<long long>(grid.rows) * grid.cols;
  if (count > kGridMaxPoints)
    lines.fail(InputErrorKind::Range, "grid " + std::to_string(grid.rows) + "×" +
                                          std::to_string(grid.cols) + " has more than " +
                                          std::to_string(kGridMaxPoints) + " points");
  const std::string declared = "the " + std::to_string(grid.rows) + "×" +
                               std::to_string(grid.cols) + " = " + std::to_string(count) +
                               " points declared on line " + std::to_string(lines.line());

  // The size is untrusted until the points are there: reserve only a sane amount.
  grid.points.reserve(static_cast<size_t>(std::min<long long>(count, 1 << 16)));
  for (long long k = 0; k < count; ++k) {
    const std::string pointName = "point " + std::to_string(k + 1) + " of " +
                                  std::to_string(count) + " (row " +
                                  std::to_string(k / grid.cols) + ", column " +
                                  std::to_string(k % grid.cols) + ")";
    if (!lines.next())
      lines.fail(InputErrorKind::Count, lines.lineAfterEnd(),
                 "file ends early: expected " + pointName + " \"x y z\" of " + declared);
    const auto& tokens = lines.tokens();
    if (tokens.size() != 3)
      lines.fail(InputErrorKind::Syntax, "expected 3 numbers \"x y z\" for " + pointName +
                                             ", found " + std::to_string(tokens.size()) +
                                             " tokens" + lines.commentHint());
    glm::dvec3 p;
    for (int c = 0; c < 3; ++c)
      p[c] = parseCoordinate(lines, tokens[c], std::string(1, "xyz"[c]) + " of " + pointName);
    grid.points.push_back(p);
  }

  if (lines.next()) {
    if (lines.tokens().size() == 3)
      lines.fail(InputErrorKind::Count, "more points than " + declared);
    lines.fail(InputErrorKind::Syntax,
               "unexpected content " + quotedToken(lines.tokens()[0]) + " after the last of " + declared);
  }
  return grid;
}

GridData readGrid(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(InputErrorKind::Io, path, 0, "is a directory, not a .grid file");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int err = errno;
    std::string reason = "cannot open for reading";
    if (err != 0) reason += ": " + std::generic_category().message(err);
    throw InputError(InputErrorKind::Io, path, 0, reason);
  }
  return parseGrid(in, path);
}

}  // namespace tessera
