#include "division/deviation.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/bernstein.h"
#include "geometry/componentwise.h"

namespace tessera {
namespace {

int latticeSteps(int cells, const DeviationSampling& s) {
  const int perCell = (s.minSamplesPerDirection + cells - 1) / cells;
  return std::max({1, s.samplesPerCell, perCell});
}

// uniformGridDeviation, starting with the row of cells at u = *hotU (when given) and recording
// there where a sample exceeded stopAbove: a search measures many grids that fail at the same
// place, and a failing grid is cheap only if that place is looked at first.
double gridDeviation(const HomogeneousNet& net, int nu, int nv, const DeviationSampling& sampling,
                     double stopAbove, double* hotU);

bool passes(const HomogeneousNet& net, int nu, int nv, double tolerance,
            const DeviationSampling& sampling, double* hotU) {
  return gridDeviation(net, nu, nv, sampling, tolerance, hotU) <= tolerance;
}

double gridDeviation(const HomogeneousNet& net, int nu, int nv, const DeviationSampling& sampling,
                     double stopAbove, double* hotU) {
  const int su = latticeSteps(nu, sampling), sv = net.m == 0 ? 1 : latticeSteps(nv, sampling);
  const int lu = nu * su, lv = nv * sv;
  const int rowStride = net.m + 1;
  std::vector<double> basisV(static_cast<size_t>(lv + 1) * rowStride);
  for (int l = 0; l <= lv; ++l) bernsteinBasis(net.m, double(l) / lv, &basisV[l * rowStride]);

  // The projected lattice points of one row of cells: (su+1) × (lv+1).
  std::vector<glm::dvec3> pts(static_cast<size_t>(su + 1) * (lv + 1));
  std::vector<glm::dvec4> column(rowStride);
  double basisU[kMaxDegree + 1];
  double sign = 0.0, worst = 0.0;
  const int firstRow = hotU ? std::min(nu - 1, std::max(0, int(*hotU * nu))) : 0;
  for (int row = 0; row < nu; ++row) {
    const int i = (firstRow + row) % nu;
    for (int a = 0; a <= su; ++a) {
      bernsteinBasis(net.n, double(i * su + a) / lu, basisU);
      for (int b = 0; b <= net.m; ++b) {
        glm::dvec4 q(0.0);
        for (int k = 0; k <= net.n; ++k) addScaled(q, basisU[k], net.at(k, b));  // componentwise.h
        column[b] = q;
      }
      for (int l = 0; l <= lv; ++l) {
        glm::dvec4 h(0.0);
        for (int b = 0; b <= net.m; ++b) addScaled(h, basisV[l * rowStride + b], column[b]);
        if (sign == 0.0) sign = h.w > 0.0 ? 1.0 : -1.0;
        if (!(h.w * sign > 0.0) || !std::isfinite(h.w)) return INFINITY;  // w meets 0
        pts[a * (lv + 1) + l] = glm::dvec3(h) / h.w;
      }
    }
    for (int j = 0; j < nv; ++j) {
      auto at = [&](int a, int b) -> const glm::dvec3& { return pts[a * (lv + 1) + j * sv + b]; };
      const glm::dvec3 &c00 = at(0, 0), &c10 = at(su, 0), &c01 = at(0, sv), &c11 = at(su, sv);
      for (int a = 0; a <= su; ++a)
        for (int b = 0; b <= sv; ++b) {
          const double x = double(a) / su, y = double(b) / sv;
          // The triangle containing (x, y): below the diagonal (c00, c10, c11), else (c00, c11, c01).
          const glm::dvec3 chord = x >= y ? (1.0 - x) * c00 + (x - y) * c10 + y * c11
                                          : (1.0 - y) * c00 + (y - x) * c01 + x * c11;
          worst = std::max(worst, glm::length(at(a, b) - chord));
          if (worst > stopAbove) {
            if (hotU) *hotU = (i + 0.5) / nu;
            return worst;
          }
        }
    }
  }
  return worst;
}

}  // namespace

double uniformGridDeviation(const HomogeneousNet& net, int nu, int nv,
                            const DeviationSampling& sampling, double stopAbove) {
  return gridDeviation(net, nu, nv, sampling, stopAbove, nullptr);
}

TrueDivisions smallestUniformGrid(const HomogeneousNet& net, double tolerance, int knownNu,
                                  int knownNv, const DeviationSampling& search,
                                  const DeviationSampling& verify) {
  TrueDivisions best;
  double hotU = 0.0;  // where the last failing grid failed
  const int maxNu = 3 * knownNu;
  int nv = net.m == 0 ? 1 : 3 * knownNv;
  // The staircase: for each N_u the smallest N_v that still passes, N_v never growing. Every
  // step that passes the coarse search lattice is a candidate, and so is the known grid.
  std::vector<std::pair<int, int>> candidates{{knownNu, net.m == 0 ? 1 : knownNv}};
  auto faces = [](const std::pair<int, int>& g) { return static_cast<long long>(g.first) * g.second; };
  bool onStaircase = false;
  for (int nu = 1; nu <= maxNu && nu < faces(candidates.front()); ++nu) {
    // Once a grid passed, one more u count keeps it passing (the assumption above; every
    // candidate is measured again below), so only a smaller N_v needs a measurement.
    if (!onStaircase) {
      ++best.evaluations;
      if (!passes(net, nu, nv, tolerance, search, &hotU)) continue;
      onStaircase = true;
    }
    // The smallest N_v that passes, below one that does: steps of 1, 2, 4, ... down while they
    // pass, then bisection (a failing grid costs little, a passing one a full measurement).
    auto passesAt = [&](int v) {
      ++best.evaluations;
      return passes(net, nu, v, tolerance, search, &hotU);
    };
    int step = 1, failing = 0;
    while (nv - step >= 1 && passesAt(nv - step)) {
      nv -= step;
      step *= 2;
    }
    failing = std::max(0, nv - step);
    while (nv - failing > 1) {
      const int mid = (nv + failing) / 2;
      (passesAt(mid) ? nv : failing) = mid;
    }
    candidates.push_back({nu, nv});
  }
  // The coarse lattice can miss a peak the verification lattice finds: the answer is the
  // smallest candidate the verification passes.
  std::stable_sort(candidates.begin(), candidates.end(),
                   [&](const auto& a, const auto& b) { return faces(a) < faces(b); });
  for (const auto& [nu, nvc] : candidates) {
    ++best.evaluations;
    best.nu = nu;
    best.nv = nvc;
    best.deviation = uniformGridDeviation(net, nu, nvc, verify);
    if (best.deviation <= tolerance) return best;
  }
  // Not even the known grid passed the verification: grow it by one in the direction that
  // costs fewer faces until it does.
  best.nu = knownNu;
  best.nv = net.m == 0 ? 1 : knownNv;
  best.deviation = uniformGridDeviation(net, best.nu, best.nv, verify);
  while (best.deviation > tolerance && best.nu < maxNu) {
    const bool growV = net.m != 0 && best.nu <= best.nv;
    best.nu += growV ? 0 : 1;
    best.nv += growV ? 1 : 0;
    ++best.evaluations;
    best.deviation = uniformGridDeviation(net, best.nu, best.nv, verify);
  }
  return best;
}

SampledSecondDerivatives sampledSecondDerivatives(const HomogeneousNet& net, int samples) {
  SampledSecondDerivatives r;
  const int sv = net.m == 0 ? 0 : samples;
  for (int a = 0; a <= samples; ++a)
    for (int b = 0; b <= sv; ++b) {
      const ProjectedSecondDerivatives d =
          projectedDerivatives(net, double(a) / samples, sv == 0 ? 0.0 : double(b) / sv);
      if (!(d.w != 0.0) || !std::isfinite(d.w)) continue;
      r.uu = std::max(r.uu, glm::length(d.puu));
      r.uv = std::max(r.uv, glm::length(d.puv));
      r.vv = std::max(r.vv, glm::length(d.pvv));
    }
  return r;
}

}  // namespace tessera
