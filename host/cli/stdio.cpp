#include "cli/stdio.h"

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>

#include "io/errors.h"
#include "io/input_limit.h"
#include "io/surface_reader.h"
#include "io/text_lines.h"

namespace tessera::cli {
namespace {

bool isOneOf(const std::string& value, std::initializer_list<const char*> names) {
  for (const char* n : names)
    if (value == n) return true;
  return false;
}

std::string extensionOf(const std::string& path) { return formatOfExtension(path); }

// Standard input whole, refusing more than kMaxStdinBytes.
std::string readStdin() {
  std::string text;
  char chunk[1 << 16];
  size_t n;
  while ((n = std::fread(chunk, 1, sizeof chunk, stdin)) > 0) {
    if (text.size() + n > kMaxStdinBytes)
      throw InputError(InputErrorKind::Range, kStdinName, 0,
                       "more than " + std::to_string(kMaxStdinBytes >> 20) +
                           " MiB on standard input; write it to a file and pass its path");
    text.append(chunk, n);
  }
  if (std::ferror(stdin))
    throw InputError(InputErrorKind::Io, kStdinName, 0,
                     std::string("read error: ") + std::strerror(errno));
  return text;
}

}  // namespace

StreamFormats parseFormats(const std::vector<std::string>& values) {
  StreamFormats formats;
  for (const std::string& v : values) {
    const bool input = isOneOf(v, {"bpt", "grid", "json"});
    const bool output = isOneOf(v, {"obj", "ply", "glb"});
    if (!input && !output)
      throw CLI::ValidationError("--format",
                                 "expected bpt, grid or json (input) or obj, ply or glb "
                                 "(output), got '" +
                                     v + "'");
    std::string& side = input ? formats.input : formats.output;
    if (!side.empty() && side != v)
      throw CLI::ValidationError("--format", "two " + std::string(input ? "input" : "output") +
                                                 " formats given: '" + side + "' and '" + v + "'");
    side = v;
  }
  return formats;
}

std::string surfaceFormat(const std::string& path, const std::string& given) {
  if (!given.empty()) return given;
  if (path == kStdioPath)
    throw InputError(InputErrorKind::Syntax, kStdinName, 0,
                     "cannot tell the format of standard input: give --format bpt, grid or json");
  return extensionOf(path);  // an unknown one is refused by parseSurface/readSurfaceFile
}

std::string meshFormat(const std::string& path, const std::string& given) {
  if (!given.empty()) return given;
  if (path == kStdioPath)
    throw InputError(InputErrorKind::Syntax, kStdoutName, 0,
                     "cannot tell the mesh format for standard output: give --format obj, ply "
                     "or glb");
  const std::string ext = extensionOf(path);
  if (!isOneOf(ext, {"obj", "ply", "glb"}))
    throw CLI::ValidationError("--output", "unknown output format '" +
                                               std::filesystem::path(path).extension().string() +
                                               "' (use .obj, .ply or .glb)");
  return ext;
}

std::vector<BezierPatch> readSurface(const std::string& path, const std::string& format) {
  if (path != kStdioPath) {
    // The extension decides, as always; a --format that agrees with it changes nothing.
    if (format == extensionOf(path)) return readSurfaceFile(path);
    std::ifstream file = openForReading(path, "a surface file");
    BoundedInput in(file, path);
    return parseSurface(in.stream(), format, path);
  }
  std::istringstream in(readStdin());
  return parseSurface(in, format, kStdinName);
}

void writeStdout(const std::string& bytes) {
  const size_t written = std::fwrite(bytes.data(), 1, bytes.size(), stdout);
  if (written != bytes.size() || std::fflush(stdout) != 0)
    throw InputError(InputErrorKind::Io, kStdoutName, 0,
                     std::string("write error: ") + std::strerror(errno));
}

}  // namespace tessera::cli
