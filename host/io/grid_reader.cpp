// .grid parsing, line by line so every error can name its line. Format and rules:
// grid_reader.h.
#include "io/grid_reader.h"

#include <algorithm>
#include <fstream>
#include <string_view>
#include <vector>

#include "common/memory_budget.h"
#include "geometry/patch.h"
#include "io/errors.h"
#include "io/input_limit.h"
#include "io/quoted_token.h"
#include "io/text_lines.h"

namespace tessera {
namespace {

int parseDimension(const TextLines& lines, std::string_view token, const char* what) {
  long long value = 0;
  bool outOfRange = false;
  if (!parseInteger(withoutPlus(token), value, outOfRange))
    lines.fail(InputErrorKind::Syntax, quotedToken(token) + " is not an integer (" + what + ")");
  if (outOfRange || value > kGridMaxPoints)
    lines.fail(InputErrorKind::Range, std::string(what) + " " + quotedToken(token) + " is too large");
  if (value < 2)
    lines.fail(InputErrorKind::Count,
               std::string(what) + " must be at least 2, found " + std::to_string(value));
  return static_cast<int>(value);
}

}  // namespace

GridData parseGrid(std::istream& in, const std::string& nameForMessages) {
  TextLines lines(in, nameForMessages);
  if (!lines.next())
    lines.fail(InputErrorKind::Count, lines.lineAfterEnd(),
               "empty file: expected the grid size \"rows cols\"");
  if (lines.tokens().size() != 2)
    lines.fail(InputErrorKind::Syntax, "expected the grid size \"rows cols\" (two integers), found " +
                                           std::to_string(lines.tokens().size()) + " tokens" +
                                           commentHint(lines.tokens()));
  GridData grid;
  grid.rows = parseDimension(lines, lines.tokens()[0], "rows");
  grid.cols = parseDimension(lines, lines.tokens()[1], "cols");
  const long long count = static_cast<long long>(grid.rows) * grid.cols;
  if (count > kGridMaxPoints)
    lines.fail(InputErrorKind::Range, "grid " + std::to_string(grid.rows) + "×" +
                                          std::to_string(grid.cols) + " has more than " +
                                          std::to_string(kGridMaxPoints) + " points");
  // Before reading the points: the grid and what interpolateGrid makes of it, per point the
  // point, five derivative arrays and four edge-point arrays (10 dvec3), per cell a bicubic
  // patch (16 control points in their own allocation).
  const uint64_t cells = uint64_t(grid.rows - 1) * uint64_t(grid.cols - 1);
  requireWithinMemoryBudget(
      uint64_t(count) * 10 * sizeof(glm::dvec3) +
          cells * (sizeof(BezierPatch) + 16 + 16 * sizeof(glm::dvec3)),
      nameForMessages + ": the " + std::to_string(grid.rows) + "×" + std::to_string(grid.cols) +
          " grid and its " + std::to_string(cells) + " bicubic patches");
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
                                             " tokens" + commentHint(lines.tokens()));
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
  std::ifstream file = openForReading(path, "a .grid file");
  BoundedInput in(file, path);
  return parseGrid(in.stream(), path);
}

}  // namespace tessera
