#include "geometry/homogeneous_net.h"

#include <array>
#include <stdexcept>
#include <string>

namespace tessera {

double binomialCoefficient(int n, int k) {
  static const auto table = [] {
    std::array<std::array<double, 65>, 65> t{};
    for (int i = 0; i <= 64; ++i) {
      t[i][0] = t[i][i] = 1.0;
      for (int j = 1; j < i; ++j) t[i][j] = t[i - 1][j - 1] + t[i - 1][j];
    }
    return t;
  }();
  if (n < 0 || n > 64) throw std::out_of_range("binomialCoefficient: n = " + std::to_string(n));
  if (k < 0 || k > n) return 0.0;
  return table[n][k];
}

HomogeneousNet toNet(const RationalBezierPatch& patch) {
  HomogeneousNet net(patch.degreeU, patch.degreeV);
  net.c = patch.cpw;
  return net;
}

HomogeneousNet toNet(const RationalBezierCurve& curve) {
  HomogeneousNet net(curve.degree, 0);
  net.c = curve.cpw;
  return net;
}

RationalBezierPatch toPatch(const HomogeneousNet& net) {
  RationalBezierPatch patch;
  patch.degreeU = net.n;
  patch.degreeV = net.m;
  patch.cpw = net.c;
  return patch;
}

ScalarNet weightsOf(const HomogeneousNet& net) {
  ScalarNet w(net.n, net.m);
  for (size_t k = 0; k < net.c.size(); ++k) w.c[k] = net.c[k].w;
  return w;
}

VectorNet numeratorsOf(const HomogeneousNet& net) {
  VectorNet p(net.n, net.m);
  for (size_t k = 0; k < net.c.size(); ++k) p.c[k] = glm::dvec3(net.c[k]);
  return p;
}

ProjectedSecondDerivatives projectedDerivatives(const HomogeneousNet& net, double u, double v) {
  const HomogeneousNet hu = hodographU(net), hv = hodographV(net);
  const glm::dvec4 h = evaluate(net, u, v);
  const glm::dvec4 du = evaluate(hu, u, v), dv = evaluate(hv, u, v);
  const glm::dvec4 duu = evaluate(hodographU(hu), u, v);
  const glm::dvec4 duv = evaluate(hodographV(hu), u, v);
  const glm::dvec4 dvv = evaluate(hodographV(hv), u, v);
  // From P = w·S differentiated (Leibniz), each S derivative in terms of lower ones.
  ProjectedSecondDerivatives d;
  d.w = h.w;
  d.p = glm::dvec3(h) / h.w;
  d.pu = (glm::dvec3(du) - du.w * d.p) / h.w;
  d.pv = (glm::dvec3(dv) - dv.w * d.p) / h.w;
  d.puu = (glm::dvec3(duu) - 2.0 * du.w * d.pu - duu.w * d.p) / h.w;
  d.puv = (glm::dvec3(duv) - du.w * d.pv - dv.w * d.pu - duv.w * d.p) / h.w;
  d.pvv = (glm::dvec3(dvv) - 2.0 * dv.w * d.pv - dvv.w * d.p) / h.w;
  return d;
}

}  // namespace tessera
