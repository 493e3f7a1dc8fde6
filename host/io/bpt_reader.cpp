// .bpt parsing, line by line so every error can name its line. Format and rules:
// bpt_reader.h.
#include "io/bpt_reader.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <system_error>

#include "io/errors.h"
#include "io/quoted_token.h"

namespace tessera {
namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Hands out the lines that carry data (skipping blank and '#' lines) split into tokens,
// and knows the line numbers for messages.
class LineSource {
 public:
  LineSource(std::istream& in, const std::string& name) : in_(in), name_(name) {}

  // Advance to the next data line; false at the end of the input.
  bool next() {
    while (std::getline(in_, text_)) {
      ++linesRead_;
      tokenize();
      if (tokens_.empty() || tokens_.front().front() == '#') continue;
      return true;
    }
    // getline sets failbit at a clean end of file too; only badbit means the read broke.
    if (in_.bad()) fail(InputErrorKind::Io, linesRead_ + 1, "read error");
    tokens_.clear();
    return false;
  }

  const std::vector<std::string_view>& tokens() const { return tokens_; }
  // The line `next()` last returned.
  int line() const { return linesRead_; }
  // Where more input was expected once `next()` has returned false: the line after the last.
  int lineAfterEnd() const { return linesRead_ + 1; }

  [[noreturn]] void fail(InputErrorKind kind, int line, const std::string& reason) const {
    throw InputError(kind, name_, line, reason);
  }
  [[noreturn]] void fail(InputErrorKind kind, const std::string& reason) const {
    fail(kind, linesRead_, reason);
  }

 private:
  void tokenize() {
    tokens_.clear();
    std::string_view rest(text_);
    size_t i = 0;
    while (i < rest.size()) {
      while (i < rest.size() && isBlank(rest[i])) ++i;
      size_t start = i;
      while (i < rest.size() && !isBlank(rest[i])) ++i;
      if (i > start) tokens_.push_back(rest.substr(start, i - start));
    }
  }

  std::istream& in_;
  const std::string& name_;
  std::string text_;
  std::vector<std::string_view> tokens_;
  int linesRead_ = 0;
};

bool parseInteger(std::string_view token, long long& value, bool& outOfRange) {
  const char* first = token.data();
  const char* last = first + token.size();
  if (first != last && *first == '+') ++first;
  auto [ptr, ec] = std::from_chars(first, last, value);
  outOfRange = ec == std::errc::result_out_of_range;
  return (ec == std::errc() || outOfRange) && ptr == last && first != last;
}

bool isInteger(std::string_view token) {
  long long value;
  bool outOfRange;
  return parseInteger(token, value, outOfRange);
}

std::string commentHint(const std::vector<std::string_view>& tokens) {
  for (std::string_view t : tokens)
    if (t.front() == '#') return " ('#' starts a comment only at the beginning of a line)";
  return "";
}

// std::from_chars is locale-independent, unlike strtod and streams.
double parseCoordinate(const LineSource& src, std::string_view token, const std::string& what) {
  const char* first = token.data();
  const char* last = first + token.size();
  // from_chars rejects an explicit '+', which other writers may emit; "+-1" stays invalid.
  if (last - first > 1 && *first == '+' && first[1] != '-' && first[1] != '+') ++first;
  double value = 0;
  auto [ptr, ec] = std::from_chars(first, last, value, std::chars_format::general);
  if (ptr != last || (ec != std::errc() && ec != std::errc::result_out_of_range))
    src.fail(InputErrorKind::Syntax, quotedToken(token) + " is not a number (" + what + ")");
  if (ec == std::errc::result_out_of_range)
    src.fail(InputErrorKind::Range,
             quotedToken(token) + " is outside the range of a double (" + what + ")");
  if (!std::isfinite(value))
    src.fail(InputErrorKind::NonFinite, quotedToken(token) + " is not a finite number (" + what + ")");
  if (std::fabs(value) > kBptMaxAbsCoordinate)
    src.fail(InputErrorKind::Range, quotedToken(token) + " exceeds the largest accepted magnitude 1e15 (" +
                                        what + ")");
  return value;
}

long long parsePatchCount(LineSource& src) {
  if (!src.next())
    src.fail(InputErrorKind::Count, src.lineAfterEnd(), "empty file: expected the patch count");
  const auto& tokens = src.tokens();
  if (tokens.size() != 1)
    src.fail(InputErrorKind::Syntax, "expected the patch count (one integer), found " +
                                         std::to_string(tokens.size()) + " tokens" +
                                         commentHint(tokens));
  long long count = 0;
  bool outOfRange = false;
  if (!parseInteger(tokens[0], count, outOfRange))
    src.fail(InputErrorKind::Syntax, quotedToken(tokens[0]) + " is not an integer patch count");
  if (outOfRange) src.fail(InputErrorKind::Count, "patch count " + quotedToken(tokens[0]) + " is too large");
  if (count < 1)
    src.fail(InputErrorKind::Count, "patch count must be at least 1, found " + std::to_string(count));
  return count;
}

int parseDegree(const LineSource& src, std::string_view token, const char* direction,
                const std::string& patchName) {
  long long degree = 0;
  bool outOfRange = false;
  if (!parseInteger(token, degree, outOfRange))
    src.fail(InputErrorKind::Syntax, quotedToken(token) + " is not an integer degree (" + direction +
                                         " of " + patchName + ")");
  if (outOfRange || degree < 1 || degree > kMaxDegree)
    src.fail(InputErrorKind::Degree, "degree in " + std::string(direction) + " of " + patchName +
                                         " is " + std::string(token) + "; must be 1.." +
                                         std::to_string(kMaxDegree));
  return static_cast<int>(degree);
}

BezierPatch parsePatch(LineSource& src, long long index, long long count) {
  const std::string patchName =
      "patch " + std::to_string(index + 1) + " of " + std::to_string(count);
  if (!src.next())
    src.fail(InputErrorKind::Count, src.lineAfterEnd(),
             "file ends early: expected the degrees \"n m\" of " + patchName);
  {
    const auto& tokens = src.tokens();
    if (tokens.size() != 2) {
      // Three tokens here usually mean the previous patch has more points than its degrees say.
      std::string hint = tokens.size() == 3 && index > 0
                             ? " (a control point? patch " + std::to_string(index) +
                                   " may have more points than its degrees allow)"
                             : commentHint(tokens);
      src.fail(InputErrorKind::Syntax, "expected the degrees \"n m\" of " + patchName +
                                           " (two integers), found " +
                                           std::to_string(tokens.size()) + " tokens" + hint);
    }
  }
  BezierPatch patch;
  patch.degreeU = parseDegree(src, src.tokens()[0], "u", patchName);
  patch.degreeV = parseDegree(src, src.tokens()[1], "v", patchName);
  const int pointCount = (patch.degreeU + 1) * (patch.degreeV + 1);
  patch.cp.resize(pointCount);

  for (int k = 0; k < pointCount; ++k) {
    const std::string pointName = "control point " + std::to_string(k + 1) + " of " +
                                  std::to_string(pointCount) + " of " + patchName;
    if (!src.next())
      src.fail(InputErrorKind::Count, src.lineAfterEnd(),
               "file ends early: expected " + pointName + " (\"x y z\")");
    const auto& tokens = src.tokens();
    if (tokens.size() != 3) {
      // Two integers here usually mean the patch is short of points and the next one began.
      std::string hint = tokens.size() == 2 && isInteger(tokens[0]) && isInteger(tokens[1])
                             ? " (a degree line? " + patchName + " needs " +
                                   std::to_string(pointCount) + " control points)"
                             : commentHint(tokens);
      src.fail(InputErrorKind::Syntax, "expected 3 numbers \"x y z\" for " + pointName +
                                           ", found " + std::to_string(tokens.size()) +
                                           " tokens" + hint);
    }
    for (int c = 0; c < 3; ++c)
      patch.cp[k][c] = parseCoordinate(src, tokens[c], std::string(1, "xyz"[c]) + " of " + pointName);
  }
  return patch;
}

}  // namespace

std::vector<BezierPatch> parseBpt(std::istream& in, const std::string& nameForMessages) {
  LineSource src(in, nameForMessages);
  const long long count = parsePatchCount(src);
  const int countLine = src.line();

  std::vector<BezierPatch> patches;
  // The count is untrusted until the patches are there: reserve only a sane amount.
  patches.reserve(static_cast<size_t>(std::min<long long>(count, 4096)));
  for (long long p = 0; p < count; ++p) patches.push_back(parsePatch(src, p, count));

  if (src.next()) {
    const auto& tokens = src.tokens();
    const std::string declared =
        "the " + std::to_string(count) + " declared on line " + std::to_string(countLine);
    if (tokens.size() == 2 && isInteger(tokens[0]) && isInteger(tokens[1]))
      src.fail(InputErrorKind::Count, "more patches than " + declared);
    src.fail(InputErrorKind::Syntax,
             "unexpected content " + quotedToken(tokens[0]) + " after the last of " + declared);
  }
  return patches;
}

std::vector<BezierPatch> readBpt(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(InputErrorKind::Io, path, 0, "is a directory, not a .bpt file");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int err = errno;
    std::string reason = "cannot open for reading";
    if (err != 0) reason += ": " + std::generic_category().message(err);
    throw InputError(InputErrorKind::Io, path, 0, reason);
  }
  return parseBpt(in, path);
}

}  // namespace tessera
