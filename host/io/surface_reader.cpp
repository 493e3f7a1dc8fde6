#include "io/surface_reader.h"

#include <filesystem>

#include "geometry/grid_interpolation.h"
#include "io/bpt_reader.h"
#include "io/errors.h"
#include "io/grid_reader.h"
#include "io/scene_reader.h"
#include "io/scene_convert.h"

namespace tessera {

std::string formatOfExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  if (!ext.empty()) ext.erase(0, 1);
  for (char& c : ext)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');  // ASCII only: no locale
  return ext;
}

std::vector<BezierPatch> readSurfaceFile(const std::string& path) {
  const std::string format = formatOfExtension(path);
  if (format == "bpt") return readBpt(path);
  if (format == "grid") return interpolateGrid(readGrid(path));
  if (format == "json") return sceneToPatches(readScene(path));
  throw InputError(InputErrorKind::Syntax, path, 0,
                   "unknown surface format '" +
                       std::filesystem::path(path).extension().string() +
                       "' (expected .bpt, .grid or .json)");
}

std::vector<BezierPatch> parseSurface(std::istream& in, const std::string& format,
                                      const std::string& nameForMessages) {
  if (format == "bpt") return parseBpt(in, nameForMessages);
  if (format == "grid") return interpolateGrid(parseGrid(in, nameForMessages));
  if (format == "json") return sceneToPatches(parseScene(in, nameForMessages));
  throw InputError(InputErrorKind::Syntax, nameForMessages, 0,
                   "unknown surface format '" + format + "' (expected bpt, grid or json)");
}

}  // namespace tessera
