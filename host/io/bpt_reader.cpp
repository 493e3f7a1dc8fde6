// .bpt parsing, line by line so every error can name its line. Format and rules:
// bpt_reader.h.
#include "io/bpt_reader.h"

#include <algorithm>
#include <fstream>
#include <string_view>

#include "common/memory_budget.h"
#include "io/errors.h"
#include "io/input_limit.h"
#include "io/quoted_token.h"
#include "io/text_lines.h"

namespace tessera {
namespace {

// The .bpt format's integers (counts, degrees) may carry any one leading '+'.
bool parseBptInteger(std::string_view token, long long& value, bool& outOfRange) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  return parseInteger(token, value, outOfRange);
}

bool isInteger(std::string_view token) {
  long long value;
  bool outOfRange;
  return parseBptInteger(token, value, outOfRange);
}

long long parsePatchCount(TextLines& src) {
  if (!src.next())
    src.fail(InputErrorKind::Count, src.lineAfterEnd(), "empty file: expected the patch count");
  const auto& tokens = src.tokens();
  if (tokens.size() != 1)
    src.fail(InputErrorKind::Syntax, "expected the patch count (one integer), found " +
                                         std::to_string(tokens.size()) + " tokens" +
                                         commentHint(tokens));
  long long count = 0;
  bool outOfRange = false;
  if (!parseBptInteger(tokens[0], count, outOfRange))
    src.fail(InputErrorKind::Syntax, quotedToken(tokens[0]) + " is not an integer patch count");
  if (outOfRange) src.fail(InputErrorKind::Count, "patch count " + quotedToken(tokens[0]) + " is too large");
  if (count < 1)
    src.fail(InputErrorKind::Count, "patch count must be at least 1, found " + std::to_string(count));
  return count;
}

int parseDegree(const TextLines& src, std::string_view token, const char* direction,
                const std::string& patchName) {
  long long degree = 0;
  bool outOfRange = false;
  if (!parseBptInteger(token, degree, outOfRange))
    src.fail(InputErrorKind::Syntax, quotedToken(token) + " is not an integer degree (" + direction +
                                         " of " + patchName + ")");
  if (outOfRange || degree < 1 || degree > kMaxDegree)
    src.fail(InputErrorKind::Degree, "degree in " + std::string(direction) + " of " + patchName +
                                         " is " + std::string(token) + "; must be 1.." +
                                         std::to_string(kMaxDegree));
  return static_cast<int>(degree);
}

BezierPatch parsePatch(TextLines& src, long long index, long long count) {
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
  TextLines src(in, nameForMessages);
  const long long count = parsePatchCount(src);
  const int countLine = src.line();

  std::vector<BezierPatch> patches;
  // The count is untrusted until the patches are there: reserve only a sane amount.
  patches.reserve(static_cast<size_t>(std::min<long long>(count, 4096)));
  // The patches held so far, each a BezierPatch and its own control-point allocation (with
  // the allocator's 16-byte header), checked as they come: the text is bounded by the
  // input-size limit, but a short patch ("1 1" and four points) costs six times its text.
  uint64_t bytes = 0;
  for (long long p = 0; p < count; ++p) {
    patches.push_back(parsePatch(src, p, count));
    bytes += sizeof(BezierPatch) + 16 + patches.back().cp.size() * sizeof(glm::dvec3);
    if (bytes > memoryBudget() / 2)  // the vector's growth may double it
      requireWithinMemoryBudget(2 * bytes, nameForMessages + ": holding " +
                                               std::to_string(p + 1) + " of its " +
                                               std::to_string(count) + " patches");
  }

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
  std::ifstream file = openForReading(path, "a .bpt file");
  BoundedInput in(file, path);
  return parseBpt(in.stream(), path);
}

}  // namespace tessera
