// Grid data → bicubic Bézier patches through uniform not-a-knot cubic splines. Method,
// parametrisation and guarantees: grid_interpolation.h.
#include "geometry/grid_interpolation.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace tessera {
namespace {

bool isFinite(const glm::dvec3& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

std::string gridSize(long long rows, long long cols) {
  return std::to_string(rows) + "×" + std::to_string(cols);
}

void validateGrid(const GridData& grid) {
  if (grid.rows < 2 || grid.cols < 2)
    throw std::invalid_argument("interpolateGrid: a grid needs at least 2×2 points, got " +
                                gridSize(grid.rows, grid.cols));
  const size_t expected = static_cast<size_t>(grid.rows) * static_cast<size_t>(grid.cols);
  if (grid.points.size() != expected)
    throw std::invalid_argument("interpolateGrid: a " + gridSize(grid.rows, grid.cols) +
                                " grid needs " + std::to_string(expected) + " points, got " +
                                std::to_string(grid.points.size()));
  for (size_t k = 0; k < grid.points.size(); ++k)
    if (!isFinite(grid.points[k]))
      throw std::invalid_argument("interpolateGrid: point (row " + std::to_string(k / grid.cols) +
                                  ", column " + std::to_string(k % grid.cols) +
                                  ") is not finite");
}

// The nodes of one grid line: `count` values starting at `first`, `stride` apart.
std::vector<glm::dvec3> gather(const std::vector<glm::dvec3>& values, size_t first,
                               size_t stride, int count) {
  std::vector<glm::dvec3> line(count);
  for (int k = 0; k < count; ++k) line[k] = values[first + k * stride];
  return line;
}

void scatter(const std::vector<glm::dvec3>& line, std::vector<glm::dvec3>& values, size_t first,
             size_t stride) {
  for (size_t k = 0; k < line.size(); ++k) values[first + k * stride] = line[k];
}

// Splines every column of `values` (fixed j, i running along u) and returns the slopes ∂/∂u
// in grid order.
std::vector<glm::dvec3> splineAlongU(const GridData& grid, const std::vector<glm::dvec3>& values) {
  std::vector<glm::dvec3> slopes(values.size());
  for (int j = 0; j < grid.cols; ++j)
    scatter(splineTangents(gather(values, j, grid.cols, grid.rows)), slopes, j, grid.cols);
  return slopes;
}

// Splines every row (fixed i, j running along v): the slopes ∂/∂v in grid order.
std::vector<glm::dvec3> splineAlongV(const GridData& grid, const std::vector<glm::dvec3>& values) {
  std::vector<glm::dvec3> slopes(values.size());
  for (int i = 0; i < grid.rows; ++i) {
    const size_t first = static_cast<size_t>(i) * grid.cols;
    scatter(splineTangents(gather(values, first, 1, grid.cols)), slopes, first, 1);
  }
  return slopes;
}

}  // namespace

std::vector<glm::dvec3> splineTangents(const std::vector<glm::dvec3>& y) {
  const size_t count = y.size();
  if (count < 2)
    throw std::invalid_argument("splineTangents: a spline needs at least 2 points, got " +
                                std::to_string(count));
  if (count == 2) return {y[1] - y[0], y[1] - y[0]};
  if (count == 3)  // the parabola: not-a-knot at the single interior knot from both sides
    return {(-3.0 * y[0] + 4.0 * y[1] - y[2]) / 2.0, (y[2] - y[0]) / 2.0,
            (y[0] - 4.0 * y[1] + 3.0 * y[2]) / 2.0};

  // Slopes m_k of the C² spline with unit knot spacing (de Boor, A Practical Guide to Splines,
  // ch. IV):   interior  m_(k-1) + 4 m_k + m_(k+1) = 3 (y_(k+1) - y_(k-1)).
  // Not-a-knot (y''' continuous at knots 1 and n-1), combined with the first/last interior
  // row to stay tridiagonal:   m_0 + 2 m_1 = (-5 y_0 + 4 y_1 + y_2) / 2,
  //                            2 m_(n-1) + m_n = (5 y_n - 4 y_(n-1) - y_(n-2)) / 2.
  // All pivots of the elimination below are ≥ 3/7 for count ≥ 4, so no pivoting is needed.
  const size_t n = count - 1;
  std::vector<double> sub(count, 1.0), diag(count, 4.0), super(count, 1.0);
  std::vector<glm::dvec3> rhs(count);
  diag[0] = 1.0;
  super[0] = 2.0;
  rhs[0] = (-5.0 * y[0] + 4.0 * y[1] + y[2]) / 2.0;
  for (size_t k = 1; k < n; ++k) rhs[k] = 3.0 * (y[k + 1] - y[k - 1]);
  sub[n] = 2.0;
  diag[n] = 1.0;
  rhs[n] = (5.0 * y[n] - 4.0 * y[n - 1] - y[n - 2]) / 2.0;

  // Thomas algorithm.
  for (size_t k = 1; k <= n; ++k) {
    const double factor = sub[k] / diag[k - 1];
    diag[k] -= factor * super[k - 1];
    rhs[k] -= factor * rhs[k - 1];
  }
  std::vector<glm::dvec3> slopes(count);
  slopes[n] = rhs[n] / diag[n];
  for (size_t k = n; k-- > 0;) slopes[k] = (rhs[k] - super[k] * slopes[k + 1]) / diag[k];
  return slopes;
}

GridDerivatives gridDerivatives(const GridData& grid) {
  validateGrid(grid);
  GridDerivatives d;
  d.tangentU = splineAlongU(grid, grid.points);
  d.tangentV = splineAlongV(grid, grid.points);
  d.twistFromTu = splineAlongV(grid, d.tangentU);
  d.twistFromTv = splineAlongU(grid, d.tangentV);
  d.twist.resize(grid.points.size());
  for (size_t k = 0; k < d.twist.size(); ++k)
    d.twist[k] = 0.5 * (d.twistFromTu[k] + d.twistFromTv[k]);
  return d;
}

std::vector<BezierPatch> interpolateGrid(const GridData& grid) {
  const GridDerivatives d = gridDerivatives(grid);
  const std::vector<glm::dvec3>& r = grid.points;

  // Edge control points, once per node, so every patch sharing a node copies the same doubles.
  const size_t nodeCount = r.size();
  std::vector<glm::dvec3> plusU(nodeCount), minusU(nodeCount), plusV(nodeCount),
      minusV(nodeCount);
  for (size_t k = 0; k < nodeCount; ++k) {
    plusU[k] = r[k] + d.tangentU[k] / 3.0;
    minusU[k] = r[k] - d.tangentU[k] / 3.0;
    plusV[k] = r[k] + d.tangentV[k] / 3.0;
    minusV[k] = r[k] - d.tangentV[k] / 3.0;
  }

  std::vector<BezierPatch> patches;
  patches.reserve(static_cast<size_t>(grid.rows - 1) * (grid.cols - 1));
  for (int i = 0; i + 1 < grid.rows; ++i) {
    for (int j = 0; j + 1 < grid.cols; ++j) {
      const size_t a = static_cast<size_t>(i) * grid.cols + j;  // corner (u, v) = (0, 0)
      const size_t b = a + grid.cols;                            // (1, 0)
      const size_t c = a + 1;                                    // (0, 1)
      const size_t e = b + 1;                                    // (1, 1)
      BezierPatch p;
      p.degreeU = 3;
      p.degreeV = 3;
      p.cp.resize(16);
      // Hermite → Bézier: b_10 = r + T^u/3, b_11 = r + T^u/3 + T^v/3 + W/9, signs flipping
      // with the side of the cell the corner is on.
      p.at(0, 0) = r[a];
      p.at(1, 0) = plusU[a];
      p.at(2, 0) = minusU[b];
      p.at(3, 0) = r[b];
      p.at(0, 3) = r[c];
      p.at(1, 3) = plusU[c];
      p.at(2, 3) = minusU[e];
      p.at(3, 3) = r[e];
      p.at(0, 1) = plusV[a];
      p.at(0, 2) = minusV[c];
      p.at(3, 1) = plusV[b];
      p.at(3, 2) = minusV[e];
      p.at(1, 1) = plusU[a] + d.tangentV[a] / 3.0 + d.twist[a] / 9.0;
      p.at(2, 1) = minusU[b] + d.tangentV[b] / 3.0 - d.twist[b] / 9.0;
      p.at(1, 2) = plusU[c] - d.tangentV[c] / 3.0 - d.twist[c] / 9.0;
      p.at(2, 2) = minusU[e] - d.tangentV[e] / 3.0 + d.twist[e] / 9.0;
      for (const glm::dvec3& q : p.cp)
        if (!isFinite(q))
          throw std::invalid_argument(
              "interpolateGrid: coordinates too large, control points of cell (row " +
              std::to_string(i) + ", column " + std::to_string(j) + ") overflow");
      patches.push_back(std::move(p));
    }
  }
  return patches;
}

}  // namespace tessera
