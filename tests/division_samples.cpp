#include "division_samples.h"

#include <algorithm>

namespace tessera::test {

std::vector<double> randomWeights(int n, int m, WeightKind kind, std::mt19937& rng) {
  std::uniform_real_distribution<double> positive(0.3, 2.0), unit(0.0, 1.0), negative(-0.6, 0.0);
  std::vector<double> w((n + 1) * (m + 1));
  std::vector<int> interior;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j) {
      const int k = i * (m + 1) + j;
      w[k] = positive(rng);
      const bool corner = (i == 0 || i == n) && (j == 0 || j == m);
      if (!corner) interior.push_back(k);
    }
  if (interior.empty()) return w;
  if (kind == WeightKind::Zeros || kind == WeightKind::AllNegativeWithZeros) {
    bool any = false;
    for (int k : interior)
      if (unit(rng) < 0.4) w[k] = 0.0, any = true;
    if (!any) w[interior[rng() % interior.size()]] = 0.0;
  }
  if (kind == WeightKind::Negative) {
    w[interior[rng() % interior.size()]] = negative(rng);
    if (unit(rng) < 0.5) w[interior[rng() % interior.size()]] = negative(rng);
  }
  if (kind == WeightKind::AllNegativeWithZeros)
    for (double& x : w) x = -x;
  return w;
}

HomogeneousNet randomNet(int n, int m, WeightKind kind, std::mt19937& rng) {
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  const std::vector<double> w = randomWeights(n, m, kind, rng);
  HomogeneousNet net(n, m);
  for (size_t k = 0; k < w.size(); ++k) {
    const glm::dvec3 p(coord(rng), coord(rng), coord(rng));
    // A zero weight keeps a finite numerator: the control point is a direction.
    net.c[k] = w[k] == 0.0 ? glm::dvec4(p, 0.0) : glm::dvec4(w[k] * p, w[k]);
  }
  return net;
}

RandomCell randomCell(int trial, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  RandomCell r;
  const int n = 1 + trial % 3, m = 1 + (trial / 3) % 3;
  r.patch = randomNet(n, m, static_cast<WeightKind>((trial / 9) % 4), rng);
  r.h = 0.02 + 0.48 * unit(rng);
  r.k = 0.02 + 0.48 * unit(rng);
  r.u0 = (1.0 - r.h) * unit(rng);
  r.v0 = (1.0 - r.k) * unit(rng);
  r.cell = subNet(r.patch, r.u0, r.u0 + r.h, r.v0, r.v0 + r.k);
  return r;
}

bool hasZeroWeight(const HomogeneousNet& net) {
  return std::any_of(net.c.begin(), net.c.end(), [](const glm::dvec4& h) { return h.w == 0; });
}

bool hasNegativeWeight(const HomogeneousNet& net) {
  return std::any_of(net.c.begin(), net.c.end(), [](const glm::dvec4& h) { return h.w < 0; });
}

}  // namespace tessera::test
