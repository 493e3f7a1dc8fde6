// Knot insertion. The Oslo algorithm (Cohen, Lyche & Riesenfeld 1980) inserts any number of
// knots at once as a matrix: new control points R = A·Q, A_ji = α_{i,p}(j), the discrete
// B-splines of the old knots x on the refined knots y (Hayashimoto et al., eq. 1–2). A is
// returned explicitly so that it can also be inverted (inverse Oslo by pseudo-inverse, §3.1
// there) and applied with applyToControlPoints / applyToNet. Boehm's single-knot insertion
// is a separate, independent route to the same answer.
#pragma once
#include <Eigen/Dense>
#include <glm/glm.hpp>
#include <vector>

#include "bspline/bspline.h"

namespace tessera {

// x with every value of `inserted` added, sorted (a multiset union).
std::vector<double> mergeKnots(const std::vector<double>& knots, std::vector<double> inserted);

// The refinement matrix A, newCount × oldCount (rows = new control points, cols = old),
// for degree p, old knots x and refined knots y, both valid knot vectors (validateKnots);
// y must contain every knot of x (with multiplicity) and lie within [x_0, x_last].
// Throws std::invalid_argument naming the violation otherwise. Every row sums to 1 where y_j ∈ [x_p, x_n), which
// for clamped knots is every row (partition of unity).
Eigen::MatrixXd osloMatrix(int degree, const std::vector<double>& oldKnots,
                           const std::vector<double>& newKnots);

// What osloMatrix asks of its knots, checked with its messages (also by to_bezier.cpp's sparse
// rows): throws std::invalid_argument naming the violation.
void validateOsloKnots(int degree, const std::vector<double>& oldKnots,
                       const std::vector<double>& newKnots);

// Row j of the Oslo matrix for degree p, coarse knots x ⊂ fine knots y: writes p + 1 values
// for columns first .. first + p (zeros where the row is shorter) and returns first. The knots
// are not validated here (osloMatrix and osloBand in banded_oslo.h do that once).
int osloRow(int degree, const std::vector<double>& x, const std::vector<double>& y, int j,
            double* values);

// y ⊇ x as multisets, both sorted.
bool knotsContain(const std::vector<double>& y, const std::vector<double>& x);

// M·cp for any M with M.cols() == cp.size() (A, or a pseudo-inverse of A).
std::vector<glm::dvec3> applyToControlPoints(const Eigen::MatrixXd& m,
                                             const std::vector<glm::dvec3>& cp);

enum class ParamDirection { U, V };

// Applies M to every column of a countU × countV net (row-major, i along u) in one
// direction: along u, M.cols() == countU and the net becomes M.rows() × countV; along v,
// M.cols() == countV and it becomes countU × M.rows(). All rows share one M because the
// tensor-product basis separates.
std::vector<glm::dvec3> applyToNet(const Eigen::MatrixXd& m, const std::vector<glm::dvec3>& cp,
                                   int countU, int countV, ParamDirection direction);

// The same curve / surface on refined knots (see osloMatrix for what newKnots must be).
BSplineCurve refineCurve(const BSplineCurve& curve, const std::vector<double>& newKnots);
BSplineSurface refineSurface(const BSplineSurface& surface, ParamDirection direction,
                             const std::vector<double>& newKnots);

// Boehm (1980): insert t ∈ [x_p, x_n] once. Throws std::invalid_argument when t lies
// outside the domain or its multiplicity would exceed degree + 1.
BSplineCurve insertKnot(const BSplineCurve& curve, double t);

}  // namespace tessera
