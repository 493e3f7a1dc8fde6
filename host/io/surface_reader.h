// Reads any surface file Tessera knows, by extension: .bpt (Newell's patch format), .grid
// (point data, interpolated into bicubic patches as in the quad-tree paper), .json (a scene,
// docs/scene_format.md, converted to patches by sceneToPatches).
#pragma once
#include <istream>
#include <string>
#include <vector>

#include "geometry/patch.h"

namespace tessera {

// The extension of `path` without its dot, in lower case ("teapot.BPT" → "bpt"; "" for none):
// formats are chosen by extension case-insensitively, as Windows and macOS name files.
std::string formatOfExtension(const std::string& path);

// Throws InputError (host/io/errors.h) naming the file, line and reason.
std::vector<BezierPatch> readSurfaceFile(const std::string& path);

// Parses a surface from `in` in `format` ("bpt", "grid" or "json"), e.g. standard input read
// into memory; `nameForMessages` stands for the file in errors ("<stdin>:12: ..."). An unknown
// format is an InputError of kind Syntax.
std::vector<BezierPatch> parseSurface(std::istream& in, const std::string& format,
                                      const std::string& nameForMessages);

}  // namespace tessera
