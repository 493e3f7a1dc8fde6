// Plain data for Bézier curves and patches (double precision, the CPU reference).
// Conventions (control-point order, normals at degenerate points, κ): docs/conventions.md.
#pragma once
#include <glm/glm.hpp>
#include <vector>

namespace tessera {

constexpr int kMaxDegree = 7;

// A polynomial Bézier curve in 3-D (2-D curves use z = 0).
struct BezierCurve {
  int degree = 3;
  std::vector<glm::dvec3> cp;  // degree + 1 points
};

// A rational Bézier curve in homogeneous form: (w·x, w·y, w·z, w), w ≥ 0.
struct RationalBezierCurve {
  int degree = 3;
  std::vector<glm::dvec4> cpw;
};

// A tensor-product Bézier patch: b_ij at cp[i*(degreeV+1) + j], i along u, j along v.
struct BezierPatch {
  int degreeU = 3;
  int degreeV = 3;
  std::vector<glm::dvec3> cp;
  // Empty: a polynomial patch. Otherwise one weight per control point (same order) and the
  // patch is the rational Σ B w b / Σ B w of the affine points cp: what scenes and the
  // tessellator carry (general_patch.h). patchPoint, patchDerivatives and
  // bicubicDerivatives evaluate it as rational (rational.h); the other polynomial functions
  // (subdivision, degree elevation, ...) refuse it.
  std::vector<double> weights;

  const glm::dvec3& at(int i, int j) const { return cp[i * (degreeV + 1) + j]; }
  glm::dvec3& at(int i, int j) { return cp[i * (degreeV + 1) + j]; }
};

// A rational tensor-product patch, homogeneous control points (w·x, w·y, w·z, w), same order.
struct RationalBezierPatch {
  int degreeU = 3;
  int degreeV = 3;
  std::vector<glm::dvec4> cpw;

  const glm::dvec4& at(int i, int j) const { return cpw[i * (degreeV + 1) + j]; }
  glm::dvec4& at(int i, int j) { return cpw[i * (degreeV + 1) + j]; }
};

// Position and partial derivatives up to third order at one (u, v).
// Third derivatives feed the limiting normal at degenerate points.
struct SurfaceDerivatives {
  glm::dvec3 p, pu, pv;
  glm::dvec3 puu, puv, pvv;
  glm::dvec3 puuu, puuv, puvv, pvvv;
};

// A table of partials, t[a][b] = ∂^(a+b)S / ∂u^a ∂v^b, as SurfaceDerivatives: every evaluator
// (Bézier, rational, B-spline) fills its own table and names the members here. Order 2 leaves
// the third-order members zero.
template <int Order, typename Table>
SurfaceDerivatives surfaceDerivativesFrom(const Table& t) {
  static_assert(Order == 2 || Order == 3, "SurfaceDerivatives holds orders 2 and 3");
  SurfaceDerivatives d;
  d.p = t[0][0];
  d.pu = t[1][0];
  d.pv = t[0][1];
  d.puu = t[2][0];
  d.puv = t[1][1];
  d.pvv = t[0][2];
  if constexpr (Order == 3) {
    d.puuu = t[3][0];
    d.puuv = t[2][1];
    d.puvv = t[1][2];
    d.pvvv = t[0][3];
  } else {
    d.puuu = d.puuv = d.puvv = d.pvvv = glm::dvec3(0.0);
  }
  return d;
}

}  // namespace tessera
