#include "geometry/surface_normal.h"

#include <cmath>
#include <limits>

namespace tessera {

namespace {

// |n| ≤ tol means this order gives no direction (the conventions' degeneracy test).
bool normaliseIfAbove(const glm::dvec3& n, double tol, glm::dvec3& out) {
  const double len = glm::length(n);
  if (!(len > tol)) return false;
  out = n / len;
  return true;
}

struct Box {
  glm::dvec3 lo{std::numeric_limits<double>::infinity()};
  glm::dvec3 hi{-std::numeric_limits<double>::infinity()};
  bool empty = true;
  void add(const glm::dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
    empty = false;
  }
  double diagonal() const { return empty ? 0.0 : glm::length(hi - lo); }
};

}  // namespace

glm::dvec3 unitNormal(const SurfaceDerivatives& d, double u, double v, double L, double eps) {
  const double tol = eps * L * L;
  glm::dvec3 n;
  if (normaliseIfAbove(glm::cross(d.pu, d.pv), tol, n)) return n;

  // Moving a distance s from (u, v) along d, Pu × Pv = s·n' + s²/2·n'' + O(s³); with the
  // zeroth term gone, the first non-vanishing term is the limiting direction, and s > 0
  // (into the patch) keeps its sign equal to that of the nearby regular normals.
  double du = 0.5 - u, dv = 0.5 - v;
  const double dl = std::sqrt(du * du + dv * dv);
  if (dl > 0.0) {
    du /= dl;
    dv /= dl;
  } else {
    du = dv = std::sqrt(0.5);
  }
  const glm::dvec3 a1 = du * d.puu + dv * d.puv;  // d/ds Pu
  const glm::dvec3 b1 = du * d.puv + dv * d.pvv;  // d/ds Pv
  if (normaliseIfAbove(glm::cross(a1, d.pv) + glm::cross(d.pu, b1), tol, n)) return n;

  const glm::dvec3 a2 = (du * du) * d.puuu + (2.0 * du * dv) * d.puuv + (dv * dv) * d.puvv;
  const glm::dvec3 b2 = (du * du) * d.puuv + (2.0 * du * dv) * d.puvv + (dv * dv) * d.pvvv;
  const glm::dvec3 n2 = glm::cross(a2, d.pv) + 2.0 * glm::cross(a1, b1) + glm::cross(d.pu, b2);
  if (normaliseIfAbove(n2, tol, n)) return n;
  return glm::dvec3(0.0);
}

double controlNetDiagonal(const BezierPatch& patch) {
  Box box;
  for (const glm::dvec3& p : patch.cp) box.add(p);
  return box.diagonal();
}

double controlNetDiagonal(const RationalBezierPatch& patch) {
  Box box;
  for (const glm::dvec4& h : patch.cpw)
    if (h.w > 0.0) box.add(glm::dvec3(h.x, h.y, h.z) / h.w);
  return box.diagonal();
}

}  // namespace tessera
