#include "general_samples.h"

#include <array>
#include <cmath>
#include <random>

namespace tessera::test {

std::vector<BezierPatch> randomGeneralPatches(size_t count, int n, int m, bool rational,
                                              bool innerZero, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> scaleDist(0.1, 10.0);
  std::uniform_real_distribution<double> weight(0.5, 2.0);
  std::vector<BezierPatch> patches(count);
  for (BezierPatch& patch : patches) {
    patch.degreeU = n;
    patch.degreeV = m;
    patch.cp.resize(size_t((n + 1) * (m + 1)));
    double scale = scaleDist(rng);
    glm::dvec3 offset(unit(rng) * 5.0, unit(rng) * 5.0, unit(rng) * 5.0);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= m; ++j)
        patch.at(i, j) = offset + scale * glm::dvec3(double(i) / n + 0.15 * unit(rng),
                                                     double(j) / m + 0.15 * unit(rng),
                                                     0.5 * unit(rng));
    if (!rational) continue;
    for (size_t k = 0; k < patch.cp.size(); ++k) patch.weights.push_back(weight(rng));
    if (innerZero) {
      std::uniform_int_distribution<int> inner(1, std::max(1, n - 1)), innerV(1, std::max(1, m - 1));
      patch.weights[size_t(inner(rng) * (m + 1) + innerV(rng))] = 0.0;
    }
  }
  return patches;
}

namespace {

// Quarter k of the unit circle as a rational quadratic: (1,0) (1,1) (0,1), weights 1 √½ 1,
// turned by exact quarter turns so that neighbouring quarters share end points bit for bit.
struct Arc {
  std::array<glm::dvec2, 3> p;
  std::array<double, 3> w;
};

Arc quarterArc(int k) {
  Arc a{{glm::dvec2(1, 0), glm::dvec2(1, 1), glm::dvec2(0, 1)}, {1.0, std::sqrt(0.5), 1.0}};
  for (int turn = 0; turn < k; ++turn)
    for (auto& p : a.p) p = glm::dvec2(-p.y, p.x);
  return a;
}

// The surface of revolution of `profile` (ρ, z) about the z axis over quarter `k` of the
// turn: b_ij = (ρ_j·a_i, z_j), w_ij = w_i·w_j.
BezierPatch revolve(const Arc& profile, int k) {
  const Arc around = quarterArc(k);
  BezierPatch p;
  p.degreeU = p.degreeV = 2;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const glm::dvec2 q = profile.p[size_t(j)];
      p.cp.push_back(glm::dvec3(q.x * around.p[size_t(i)].x, q.x * around.p[size_t(i)].y, q.y));
      p.weights.push_back(around.w[size_t(i)] * profile.w[size_t(j)]);
    }
  return p;
}

Arc scaled(Arc a, double radius, glm::dvec2 centre) {
  for (auto& p : a.p) p = centre + radius * p;
  return a;
}

}  // namespace

std::vector<BezierPatch> rationalTorus(double major, double minor) {
  std::vector<BezierPatch> patches;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      patches.push_back(revolve(scaled(quarterArc(b), minor, glm::dvec2(major, 0.0)), a));
  return patches;
}

std::vector<BezierPatch> rationalSphere(double radius) {
  std::vector<BezierPatch> patches;
  for (int a = 0; a < 4; ++a)
    for (int b : {3, 0})  // the profile from the south pole up through the equator
      patches.push_back(revolve(scaled(quarterArc(b), radius, glm::dvec2(0.0)), a));
  return patches;
}

BezierPatch rationalQuarterCylinder(double radius, double height) {
  const Arc arc = quarterArc(0);
  BezierPatch p;
  p.degreeU = 2;
  p.degreeV = 1;
  for (int i = 0; i < 3; ++i)
    for (double z : {0.0, height}) {
      p.cp.push_back(glm::dvec3(radius * arc.p[size_t(i)], z));
      p.weights.push_back(arc.w[size_t(i)]);
    }
  return p;
}

}  // namespace tessera::test
