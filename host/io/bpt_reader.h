// Reader for the .bpt text format (Bézier patches; the Utah tea set ships in it).
//
//   <patch count>
//   per patch:  <n> <m>          degrees in u and v, each 1..kMaxDegree
//               (n+1)(m+1) lines "x y z", control points row by row: b_00 b_01 … b_0m b_10 …
//
// The row order is the BezierPatch order (b_ij at cp[i*(m+1)+j], i along u), see
// docs/conventions.md. The reader is strict, because a silently misread control net shows up
// much later as a wrong surface:
//   - the count is an integer ≥ 1 (Count otherwise);
//   - exactly one token on the count line, two on a degree line, three on a point line;
//   - the count must equal the patches present: a file that ends early, or carries another
//     patch after the declared ones, is a Count error naming the line concerned;
//   - every coordinate finite (NonFinite) with |value| ≤ 1e15 (Range), so later squared
//     lengths and bounding-box diagonals stay far from overflow;
//   - numbers are parsed without regard to the C/C++ locale (a German locale's decimal comma
//     does not change what "1.5" means); a leading '+' is accepted, hex floats are not.
// Blank lines and lines whose first non-blank character is '#' are skipped anywhere; a '#'
// after data on the same line is an error (not a comment). Line ends may be LF or CRLF.
// Errors are InputError (host/io/errors.h) with the 1-based line of the offending line, or of
// the line where more input was expected when the file ends early.
#pragma once
#include <istream>
#include <string>
#include <vector>

#include "geometry/patch.h"
#include "io/text_lines.h"

namespace tessera {

// Largest accepted |coordinate| in a .bpt file.
constexpr double kBptMaxAbsCoordinate = kMaxAbsInputCoordinate;  // io/text_lines.h

// Read the file at `path`; an unreadable file is an InputError of kind Io.
std::vector<BezierPatch> readBpt(const std::string& path);

// Parse .bpt text from `in`; `nameForMessages` stands for the file in error messages.
std::vector<BezierPatch> parseBpt(std::istream& in, const std::string& nameForMessages);

}  // namespace tessera
