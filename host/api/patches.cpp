// The public API's surfaces: loading files and building patches from flat arrays.
#include <stdexcept>

#include "api/convert.h"
#include "common/version.h"
#include "io/surface_reader.h"
#include "quadtree/tolerance.h"
#include "tessera/tessera.h"

namespace tessera {

const char* version() { return versionString(); }  // the project() version

std::vector<Patch> loadPatches(const std::string& path) {
  try {
    return api::toPatches(readSurfaceFile(path));
  } catch (const std::invalid_argument& e) {
    throw ArgumentError(path + ": " + e.what());
  }
}

std::vector<Patch> patchesFromArrays(int degreeU, int degreeV, size_t patchCount, const double* xyz,
                                     const double* weights) {
  if (degreeU < 1 || degreeU > kMaxDegree || degreeV < 1 || degreeV > kMaxDegree)
    throw ArgumentError("patchesFromArrays: degree " + std::to_string(degreeU) + "x" +
                        std::to_string(degreeV) + " is outside 1..7");
  if (patchCount > 0 && xyz == nullptr)
    throw ArgumentError("patchesFromArrays: no control points for " + std::to_string(patchCount) +
                        " patches");
  const size_t count = size_t(degreeU + 1) * size_t(degreeV + 1);
  std::vector<Patch> patches(patchCount);
  for (size_t k = 0; k < patchCount; ++k) {
    Patch& p = patches[k];
    p.degreeU = degreeU;
    p.degreeV = degreeV;
    p.points.assign(xyz + 3 * count * k, xyz + 3 * count * (k + 1));
    if (weights) p.weights.assign(weights + count * k, weights + count * (k + 1));
  }
  return patches;
}

double boundingBoxDiagonal(const std::vector<Patch>& patches) {
  const std::vector<BezierPatch> internal = api::toBezierPatches(patches);
  try {
    return controlPointDiagonal(internal);
  } catch (const std::invalid_argument& e) {
    throw ArgumentError(e.what());
  }
}

double relativeTolerance(const std::vector<Patch>& patches, double fraction) {
  if (!(fraction > 0 && fraction <= 1))
    throw ArgumentError("relativeTolerance: the fraction must be in (0, 1], got " +
                        std::to_string(fraction));
  return fraction * boundingBoxDiagonal(patches);
}

}  // namespace tessera
