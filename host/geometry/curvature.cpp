#include "geometry/curvature.h"

#include <algorithm>
#include <cmath>

namespace tessera {

SurfaceCurvature surfaceCurvature(const SurfaceDerivatives& d, double L, double eps) {
  SurfaceCurvature c;
  const glm::dvec3 cr = glm::cross(d.pu, d.pv);
  const double area = glm::length(cr);
  // EG − F² = |Pu × Pv|² (Lagrange's identity): testing |Pu × Pv| makes this flag agree with
  // unitNormal's degeneracy test exactly and avoids the cancellation in EG − F².
  if (!(area > eps * L * L)) {
    c.degenerate = true;
    return c;
  }
  const glm::dvec3 n = cr / area;
  const double E = glm::dot(d.pu, d.pu), F = glm::dot(d.pu, d.pv), G = glm::dot(d.pv, d.pv);
  const double L2 = glm::dot(d.puu, n), M2 = glm::dot(d.puv, n), N2 = glm::dot(d.pvv, n);
  const double det = area * area;
  c.gaussian = (L2 * N2 - M2 * M2) / det;
  c.mean = (E * N2 - 2.0 * F * M2 + G * L2) / (2.0 * det);
  const double root = std::sqrt(std::max(c.mean * c.mean - c.gaussian, 0.0));
  c.k1 = c.mean + root;
  c.k2 = c.mean - root;
  c.kappa = std::abs(c.mean) + root;

  // Directions: the shape operator in the orthonormal tangent frame e1 = Pu/|Pu|, e2 = n × e1
  // is symmetric, S = J⁻ᵀ II J⁻¹ with J = [[|Pu|, Pv·e1], [0, Pv·e2]] the frame coordinates
  // of Pu and Pv; its eigenvectors are orthonormal even at umbilics, where solving
  // (II − k I)x = 0 in the (Pu, Pv) basis has no unique answer.
  const double a11 = glm::length(d.pu);
  const glm::dvec3 e1 = d.pu / a11;
  const glm::dvec3 e2 = glm::cross(n, e1);
  const double a12 = glm::dot(d.pv, e1), a22 = area / a11;  // Pv·e2 = |Pu × Pv| / |Pu|
  const double c2x = -a12 / (a11 * a22), c2y = 1.0 / a22;   // second column of J⁻¹
  const double s11 = L2 / (a11 * a11);
  const double s12 = (L2 * c2x + M2 * c2y) / a11;
  const double s22 = L2 * c2x * c2x + 2.0 * M2 * c2x * c2y + N2 * c2y * c2y;
  // The larger eigenvalue's eigenvector of [[s11, s12], [s12, s22]] is at angle θ.
  const double theta = 0.5 * std::atan2(2.0 * s12, s11 - s22);
  c.dir1 = std::cos(theta) * e1 + std::sin(theta) * e2;
  c.dir2 = glm::cross(n, c.dir1);
  return c;
}

}  // namespace tessera
