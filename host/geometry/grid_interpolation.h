// Data interpolation by bicubic Bézier patches (section 3 of the quad-tree paper,
// papers/000): a grid of surface points r_ij becomes one bicubic patch per grid cell.
//
//   1. the grid points r_ij, i = 0..rows-1 along u, j = 0..cols-1 along v;
//   2. each sequence r_0j, r_1j, … (fixed j) is interpolated by a cubic spline: u tangents T^u_ij;
//   3. each sequence r_i0, r_i1, … (fixed i) likewise: v tangents T^v_ij;
//   4./5. the tangent sequences are splined across: T^u along v and T^v along u give two
//      twist estimates W_ij, which are averaged (see below: they agree up to rounding);
//   6. cell (i, j) becomes the Hermite patch of its four corners' r, T^u, T^v, W, written in
//      Bézier form.
// (As printed, steps 4 and 5 spline T^u_0j … T^u_nj along u, which would give ∂²r/∂u², not a
// twist; the twist ∂²r/∂u∂v needs T^u splined along v, which is what is done here.)
//
// Parametrisation: uniform, one unit of parameter per grid step in each direction (u = i,
// v = j), and patch (i, j) maps its cell [i, i+1] × [j, j+1] to [0,1]² by translation only.
// Tangents therefore need no rescaling per cell and the patches are C¹ (indeed C²) in the
// per-patch parameters as well as in the global ones.
//
// Spline: the C² cubic spline with not-a-knot end conditions (de Boor). Unlike natural end
// conditions, which force zero second derivative at the border and flatten every curved data
// set there, not-a-knot reproduces any cubic exactly, so a grid sampled from a bicubic
// polynomial (a plane, z = x² + y², …) on uniform spacing is reproduced to rounding, border
// cells included. With 3 points along a direction it is the interpolating parabola, with 2 the
// straight line (the cubic spline is then undetermined).
//
// Because the spline's slopes are a linear map of its values, splining T^u along v and T^v
// along u apply the same two linear maps in the two orders, which commute: the twist
// estimates are equal in exact arithmetic, and the result is the tensor-product (bicubic)
// not-a-knot spline interpolant, C² across cell boundaries.
//
// Shared boundaries are bit-identical: every boundary control point is computed once per grid
// node (r, r ± T^u/3, r ± T^v/3) and copied into each patch that uses it, so neighbouring
// patches hold the same doubles on their common edge (for watertight meshing).
#pragma once
#include <glm/glm.hpp>
#include <vector>

#include "geometry/patch.h"

namespace tessera {

// A rows × cols grid of surface points, row-major: r_ij at points[i*cols + j], i (the row)
// along u, j (the column) along v.
struct GridData {
  int rows = 0;
  int cols = 0;
  std::vector<glm::dvec3> points;

  const glm::dvec3& at(int i, int j) const { return points[static_cast<size_t>(i) * cols + j]; }
};

// The derivative data of steps 2–5, one value per grid node in GridData order.
struct GridDerivatives {
  std::vector<glm::dvec3> tangentU;     // T^u_ij = ∂r/∂u
  std::vector<glm::dvec3> tangentV;     // T^v_ij = ∂r/∂v
  std::vector<glm::dvec3> twistFromTu;  // T^u splined along v
  std::vector<glm::dvec3> twistFromTv;  // T^v splined along u
  std::vector<glm::dvec3> twist;        // their average, used for the patches
};

// Slopes at the nodes of the not-a-knot cubic spline through `points` at parameters
// 0, 1, …, size-1 (2 points: the chord; 3: the parabola). Throws std::invalid_argument for
// fewer than 2 points.
std::vector<glm::dvec3> splineTangents(const std::vector<glm::dvec3>& points);

// Steps 2–5. Throws as interpolateGrid.
GridDerivatives gridDerivatives(const GridData& grid);

// Steps 1–6: (rows-1)·(cols-1) bicubic patches, patch of cell (i, j) at [i*(cols-1) + j],
// with b_00 = r_ij, b_30 = r_(i+1)j, b_03 = r_i(j+1), b_33 = r_(i+1)(j+1) exactly.
// Throws std::invalid_argument for fewer than 2 rows or columns, a point count other than
// rows·cols, a non-finite point, or coordinates so large that the control points overflow.
std::vector<BezierPatch> interpolateGrid(const GridData& grid);

}  // namespace tessera
