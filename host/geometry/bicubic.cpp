#include "geometry/bicubic.h"

#include <stdexcept>
#include <string>

#include "geometry/rational.h"

namespace tessera {

namespace {

// The rows of the cubic de Casteljau triangle at t: B_i,3, B_i,2, B_i,1.
struct CubicRows {
  double b3[4], b2[3], b1[2];
};

CubicRows cubicRows(double t) {
  const double s = 1.0 - t;
  return {{s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t},
          {s * s, 2.0 * t * s, t * t},
          {s, t}};
}

// d^order/dt^order of the cubic with control points q, in difference form (as in
// tensorPartial, host/geometry/bernstein.h) so that equal control points give exactly zero.
glm::dvec3 cubicDerivative(const glm::dvec3 (&q)[4], const CubicRows& r, int order) {
  switch (order) {
    case 0:
      return r.b3[0] * q[0] + r.b3[1] * q[1] + r.b3[2] * q[2] + r.b3[3] * q[3];
    case 1:
      return 3.0 * (r.b2[0] * (q[1] - q[0]) + r.b2[1] * (q[2] - q[1]) + r.b2[2] * (q[3] - q[2]));
    case 2: {
      const glm::dvec3 d0 = q[1] - q[0], d1 = q[2] - q[1], d2 = q[3] - q[2];
      return 6.0 * (r.b1[0] * (d1 - d0) + r.b1[1] * (d2 - d1));
    }
    default: {
      const glm::dvec3 d0 = q[1] - q[0], d1 = q[2] - q[1], d2 = q[3] - q[2];
      return 6.0 * ((d2 - d1) - (d1 - d0));
    }
  }
}

SurfaceDerivatives bicubicFromNet(const glm::dvec3* cp, double u, double v) {
  const CubicRows bu = cubicRows(u);
  const CubicRows bv = cubicRows(v);
  // alongU[a][i] = row i of the net differenced a times along u (rows 0..3−a). Differencing
  // before any sum keeps the error of ∂u relative to the patch's size, not its distance from
  // the origin; summing rows first (as the fp32 shader does) would not.
  glm::dvec3 alongU[4][4][4];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) alongU[0][i][j] = cp[4 * i + j];
  for (int a = 1; a < 4; ++a)
    for (int i = 0; i < 4 - a; ++i)
      for (int j = 0; j < 4; ++j) alongU[a][i][j] = alongU[a - 1][i + 1][j] - alongU[a - 1][i][j];

  static constexpr double kOne[1] = {1.0};
  static constexpr double kFalling[4] = {1.0, 3.0, 6.0, 6.0};  // 3!/(3−a)!
  const double* weightU[4] = {bu.b3, bu.b2, bu.b1, kOne};      // B_i,3−a(u)
  auto partial = [&](int a, int b) {
    glm::dvec3 sum(0.0);
    for (int i = 0; i < 4 - a; ++i) sum += weightU[a][i] * cubicDerivative(alongU[a][i], bv, b);
    return kFalling[a] * sum;
  };
  SurfaceDerivatives d;
  d.p = partial(0, 0);
  d.pu = partial(1, 0);
  d.pv = partial(0, 1);
  d.puu = partial(2, 0);
  d.puv = partial(1, 1);
  d.pvv = partial(0, 2);
  d.puuu = partial(3, 0);
  d.puuv = partial(2, 1);
  d.puvv = partial(1, 2);
  d.pvvv = partial(0, 3);
  return d;
}

}  // namespace

SurfaceDerivatives bicubicDerivatives(const BicubicNet& cp, double u, double v) {
  return bicubicFromNet(cp.data(), u, v);
}

SurfaceDerivatives bicubicDerivatives(const BezierPatch& patch, double u, double v) {
  if (patch.degreeU != 3 || patch.degreeV != 3 || patch.cp.size() != 16)
    throw std::invalid_argument(
        "bicubicDerivatives: needs a degree-(3, 3) patch with 16 control "
        "points, got degree (" +
        std::to_string(patch.degreeU) + ", " + std::to_string(patch.degreeV) + ") with " +
        std::to_string(patch.cp.size()));
  if (!patch.weights.empty()) return rationalPatchDerivatives(toRationalPatch(patch), u, v);
  return bicubicFromNet(patch.cp.data(), u, v);
}

}  // namespace tessera
