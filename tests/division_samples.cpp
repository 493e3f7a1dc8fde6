#include "division_samples.h"

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

}  // namespace tessera::test
