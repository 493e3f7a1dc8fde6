#include "patch_samples.h"

#include <cmath>
#include <random>

namespace tessera::test {

std::vector<BezierPatch> randomBicubicPatches(size_t count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> scaleDist(0.1, 10.0);
  std::vector<BezierPatch> patches(count);
  for (BezierPatch& patch : patches) {
    patch.degreeU = patch.degreeV = 3;
    patch.cp.resize(16);
    double scale = scaleDist(rng);
    glm::dvec3 offset(unit(rng) * 5.0, unit(rng) * 5.0, unit(rng) * 5.0);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        patch.at(i, j) = offset + scale * glm::dvec3(i / 3.0 + 0.15 * unit(rng),
                                                     j / 3.0 + 0.15 * unit(rng), 0.5 * unit(rng));
  }
  return patches;
}

std::vector<BezierPatch> collapsedEdgePatches() {
  std::vector<BezierPatch> patches;
  // A dome quarter: row i = 0 collapsed to the apex (u = 0 edge), as on the teapot lid.
  BezierPatch dome;
  dome.cp.resize(16);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double r = i / 3.0;
      double a = (M_PI / 2) * j / 3.0;
      dome.at(i, j) = glm::dvec3(r * std::cos(a), r * std::sin(a), 1.0 - r * r);
    }
  patches.push_back(dome);
  // The same dome with its apex on the v = 1 edge (transposed and flipped).
  BezierPatch flipped = dome;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) flipped.at(i, j) = dome.at(3 - j, i);
  patches.push_back(flipped);
  // A triangle-like patch with two collapsed edges meeting at one corner region.
  BezierPatch wedge = dome;
  for (int j = 0; j < 4; ++j) wedge.at(3, j) = wedge.at(3, 0) * 0.5 + wedge.at(3, 3) * 0.5;
  patches.push_back(wedge);
  return patches;
}

std::vector<gpu::EvalQuery> gridQueries(size_t patchCount, int n, int extra, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<gpu::EvalQuery> queries;
  for (uint32_t p = 0; p < patchCount; ++p) {
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        queries.push_back({p, float(a) / float(n - 1), float(b) / float(n - 1), 0});
    for (int k = 0; k < extra; ++k) queries.push_back({p, unit(rng), unit(rng), 0});
  }
  return queries;
}

}  // namespace tessera::test
