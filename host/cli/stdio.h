// `-` for standard input and output, and --format for when no extension can tell the format.
// Input is read whole into memory (with a size limit) and parsed from there, named "<stdin>"
// in messages; output is built whole in memory and written only once the command succeeded.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "geometry/patch.h"

namespace tessera::cli {

constexpr const char* kStdioPath = "-";
constexpr const char* kStdinName = "<stdin>";
constexpr const char* kStdoutName = "<stdout>";
// The most bytes read from standard input; more is refused (exit 2) rather than swapping.
constexpr size_t kMaxStdinBytes = size_t(1) << 30;

// The --format values (each names an input format, bpt|grid|json, or an output one,
// obj|ply|glb; the two sets are disjoint, so one option serves both sides).
struct StreamFormats {
  std::string input;   // "" when not given
  std::string output;  // "" when not given
};
// Sorts `values` into input and output formats; CLI::ValidationError naming --format for an
// unknown value or two values for one side.
StreamFormats parseFormats(const std::vector<std::string>& values);

// The surface format of `path`: `given` when set, else the extension without its dot. For `-`
// without `given`, an InputError (exit 2) naming <stdin> and asking for --format.
std::string surfaceFormat(const std::string& path, const std::string& given);
// The mesh format of `path` as above (obj, ply or glb); an unknown extension is a
// CLI::ValidationError naming --output, `-` without `given` an InputError naming <stdout>.
std::string meshFormat(const std::string& path, const std::string& given);

// Reads the surface at `path` (`-`: standard input, at most kMaxStdinBytes) in `format`.
std::vector<BezierPatch> readSurface(const std::string& path, const std::string& format);

// Writes all of `bytes` to standard output and flushes; InputError of kind Io naming <stdout>
// when that fails (a closed pipe, a full disk).
void writeStdout(const std::string& bytes);

}  // namespace tessera::cli
