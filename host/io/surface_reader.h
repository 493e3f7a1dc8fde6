// Reads any surface file Tessera knows, by extension: .bpt (Newell's patch format), .grid
// (point data, interpolated into bicubic patches as in the quad-tree paper), .json (a scene,
// docs/scene_format.md, converted to patches by sceneToPatches).
#pragma once
#include <string>
#include <vector>

#include "geometry/patch.h"

namespace tessera {

// Throws InputError (host/io/errors.h) naming the file, line and reason.
std::vector<BezierPatch> readSurfaceFile(const std::string& path);

}  // namespace tessera
