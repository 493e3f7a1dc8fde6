#include "io/vertex_selection.h"

#include <sstream>
#include <stdexcept>
#include <string_view>

#include "io/errors.h"
#include "io/input_limit.h"
#include "io/quoted_token.h"
#include "io/text_lines.h"

namespace tessera {
namespace {

struct TokenError {
  InputErrorKind kind;
  std::string reason;
};

// One 1-based vertex number of a token, or what is wrong with it.
bool parseVertexNumber(std::string_view text, std::string_view token, uint32_t vertexCount,
                       uint32_t& number, TokenError& error) {
  long long value = 0;
  bool outOfRange = false;
  if (!parseInteger(text, value, outOfRange)) {
    error = {InputErrorKind::Syntax, quotedToken(token) + " is not a vertex number or a range a-b"};
    return false;
  }
  if (!outOfRange && value < 1) {
    error = {InputErrorKind::Range,
             "vertex " + quotedToken(text) + ": OBJ vertex numbers start at 1"};
    return false;
  }
  if (outOfRange || value > (long long)vertexCount) {
    error = {InputErrorKind::Range, "vertex " + quotedToken(text) + " is past the mesh's " +
                                        std::to_string(vertexCount) + " vertices"};
    return false;
  }
  number = uint32_t(value);
  return true;
}

// The range of `token` ("n" or "a-b", 1-based); false with `error` set when it is not one.
bool parseToken(std::string_view token, uint32_t vertexCount, uint32_t& first, uint32_t& last,
                TokenError& error) {
  // A '-' after the first character separates a range; a leading '-' is a (refused) sign.
  const size_t dash = token.find('-', 1);
  if (!parseVertexNumber(token.substr(0, dash), token, vertexCount, first, error)) return false;
  last = first;
  if (dash != std::string_view::npos &&
      !parseVertexNumber(token.substr(dash + 1), token, vertexCount, last, error))
    return false;
  if (last < first) {
    error = {InputErrorKind::Range, "the range " + quotedToken(token) + " runs backwards"};
    return false;
  }
  return true;
}

void mark(std::vector<uint8_t>& chosen, uint32_t first, uint32_t last) {
  for (uint64_t v = first; v <= last; ++v) chosen[v - 1] = 1;
}

// Calls mark(token) for each comma-separated part of each blank-separated token of a line,
// up to a token starting with '#'.
template <class Mark>
void forEachToken(const std::vector<std::string_view>& tokens, Mark mark) {
  for (std::string_view t : tokens) {
    if (t.front() == '#') return;
    while (!t.empty()) {
      const size_t comma = t.find(',');
      if (comma != 0) mark(t.substr(0, comma));
      if (comma == std::string_view::npos) break;
      t.remove_prefix(comma + 1);
    }
  }
}

std::vector<uint32_t> indicesOf(const std::vector<uint8_t>& chosen) {
  std::vector<uint32_t> out;
  for (uint32_t v = 0; v < chosen.size(); ++v)
    if (chosen[v]) out.push_back(v);
  return out;
}

}  // namespace

std::vector<uint32_t> parseVertexSelection(std::istream& in, const std::string& name,
                                           uint32_t vertexCount) {
  TextLines lines(in, name);
  std::vector<uint8_t> chosen(vertexCount, 0);
  bool any = false;
  while (lines.next())
    forEachToken(lines.tokens(), [&](std::string_view token) {
      TokenError error;
      uint32_t first = 0, last = 0;
      if (!parseToken(token, vertexCount, first, last, error))
        lines.fail(error.kind, lines.line(), error.reason);
      mark(chosen, first, last);
      any = true;
    });
  if (!any) lines.fail(InputErrorKind::Count, 0, "names no vertex (expected 1-based vertex numbers)");
  return indicesOf(chosen);
}

std::vector<uint32_t> readVertexSelection(const std::string& path, uint32_t vertexCount) {
  std::ifstream file = openForReading(path, "a vertex selection file");
  BoundedInput in(file, path);
  return parseVertexSelection(in.stream(), path, vertexCount);
}

namespace {

// Each range of a command-line list, or std::invalid_argument.
template <class Use>
void forEachListedRange(const std::string& text, uint32_t vertexCount, Use use) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string word; in >> word;) words.push_back(word);
  const std::vector<std::string_view> tokens(words.begin(), words.end());
  bool any = false;
  forEachToken(tokens, [&](std::string_view token) {
    TokenError error;
    uint32_t first = 0, last = 0;
    if (!parseToken(token, vertexCount, first, last, error)) throw std::invalid_argument(error.reason);
    use(first, last);
    any = true;
  });
  if (!any) throw std::invalid_argument("names no vertex (expected 1-based vertex numbers)");
}

}  // namespace

void checkVertexList(const std::string& text) {
  forEachListedRange(text, UINT32_MAX, [](uint32_t, uint32_t) {});
}

std::vector<uint32_t> parseVertexList(const std::string& text, uint32_t vertexCount) {
  std::vector<uint8_t> chosen(vertexCount, 0);
  forEachListedRange(text, vertexCount,
                     [&](uint32_t first, uint32_t last) { mark(chosen, first, last); });
  return indicesOf(chosen);
}

}  // namespace tessera
