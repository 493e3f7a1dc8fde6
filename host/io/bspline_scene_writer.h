// Writes B-spline surfaces as a Tessera JSON scene (the format of host/io/scene_reader.h,
// docs/scene_format.md), so `tessera render` can picture them. Atomic (atomic_file.h).
#pragma once
#include <string>
#include <vector>

#include "bspline/bspline.h"

namespace tessera {

struct NamedBSpline {
  std::string name;
  const BSplineSurface* surface = nullptr;
};

// Coordinates and knots with 17 significant digits (they read back exactly). Throws
// InputError (kind Io) naming `path` when it cannot be written.
void writeBSplineScene(const std::string& path, const std::vector<NamedBSpline>& surfaces);

}  // namespace tessera
