// Reader for the .grid text format: a rows × cols grid of surface points r_ij, the input of
// the data interpolation in grid_interpolation.h.
//
//   # a comment
//   <rows> <cols>                 integers, each ≥ 2
//   rows·cols lines "x y z"       row by row: r_00 r_01 … r_0(cols-1) r_10 …
//
// Row i runs along u, column j along v (GridData order, point r_ij at index i*cols + j);
// with rows along x and columns along y the interpolated surface's normal Pu × Pv points to
// +z. The rules are those of the .bpt reader (bpt_reader.h):
//   - exactly two tokens on the size line and three on a point line (Syntax otherwise);
//   - rows and cols are integers ≥ 2 (Count) and rows·cols ≤ kGridMaxPoints (Range);
//   - exactly rows·cols points: a file that ends early, or carries anything after the last
//     point, is a Count error naming the line concerned;
//   - every coordinate finite (NonFinite) with |value| ≤ 1e15 (Range);
//   - numbers are parsed independently of the C/C++ locale; a leading '+' is accepted.
// Blank lines and lines whose first non-blank character is '#' are skipped anywhere; a '#'
// after data on the same line is an error (not a comment). Line ends may be LF or CRLF.
// Errors are InputError (host/io/errors.h) whose what() reads "<file>:<line>: <reason>".
#pragma once
#include <istream>
#include <string>

#include "geometry/grid_interpolation.h"
#include "io/text_lines.h"

namespace tessera {

// Largest accepted |coordinate| in a .grid file, as in .bpt.
constexpr double kGridMaxAbsCoordinate = kMaxAbsInputCoordinate;  // io/text_lines.h
// Largest accepted rows·cols (a header beyond it is taken for a corrupt file).
constexpr long long kGridMaxPoints = 1LL << 26;

// Read the file at `path`; an unreadable file is an InputError of kind Io.
GridData readGrid(const std::string& path);

// Parse .grid text from `in`; `nameForMessages` stands for the file in error messages.
GridData parseGrid(std::istream& in, const std::string& nameForMessages);

}  // namespace tessera
