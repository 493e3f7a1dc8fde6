// Work shared by the benchmarks: perturbed copies of a model, random bicubic patches.
#pragma once
#include <cmath>
#include <random>
#include <vector>

#include "geometry/patch.h"

namespace tessera::bench {

// `count` copies of `model`, each moved and bent by its own smooth deformation field, so no
// two are identical while coincident control points (collapsed edges, shared boundaries) stay
// coincident: independent jitter would turn the teapot lid's collapsed edge into a crinkle
// that never tests flat. Copies sit on a grid `perRow` wide, 8 units apart.
inline std::vector<BezierPatch> perturbedCopies(const std::vector<BezierPatch>& model, int count,
                                                int perRow = 40) {
  std::mt19937 rng(1234);
  std::uniform_real_distribution<double> phase(0.0, 6.2831853);
  std::vector<BezierPatch> out;
  out.reserve(model.size() * size_t(count));
  for (int c = 0; c < count; ++c) {
    glm::dvec3 offset(double(c % perRow) * 8.0, double(c / perRow) * 8.0, 0.0);
    double a = phase(rng), b = phase(rng), d = phase(rng);
    for (BezierPatch p : model) {
      for (auto& cp : p.cp)
        cp += offset + glm::dvec3(0.02 * std::sin(1.3 * cp.y + a), 0.02 * std::sin(1.1 * cp.z + b),
                                  0.02 * std::sin(0.9 * cp.x + d));
      out.push_back(p);
    }
  }
  return out;
}

// Random bicubic patches over the unit cells of a 4×4 net, jittered: smooth, no degeneracy.
inline std::vector<BezierPatch> randomPatches(size_t count, uint32_t seed = 7) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<BezierPatch> out(count);
  for (auto& p : out) {
    p.cp.resize(16);
    for (int k = 0; k < 16; ++k)
      p.cp[k] = glm::dvec3(double(k / 4) + unit(rng) * 0.3, double(k % 4) + unit(rng) * 0.3,
                           unit(rng));
  }
  return out;
}

}  // namespace tessera::bench
