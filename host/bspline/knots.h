// Knot vectors for B-splines: construction, validation and span search.
// A spline of degree p with n control points has n + p + 1 knots x_0..x_{n+p}; its
// parameter domain is [x_p, x_n] (the knots outside it only shape the end pieces).
#pragma once
#include <vector>

namespace tessera {

// Evenly spaced knots first, first + spacing, ..., n + p + 1 of them (unclamped: the curve
// does not pass through its end control points).
std::vector<double> uniformKnots(int degree, int controlCount, double first = 0.0,
                                 double spacing = 1.0);

// Open uniform (clamped) knots on [a, b]: a repeated p + 1 times, n - p - 1 evenly spaced
// interior knots, b repeated p + 1 times. With n = p + 1 this is (a..a, b..b), the Bézier
// case (Taniguchi 2000, §2.2.2).
std::vector<double> openUniformKnots(int degree, int controlCount, double a = 0.0, double b = 1.0);

// Throws std::invalid_argument naming the reason unless: 1 ≤ degree ≤ kMaxDegree,
// controlCount ≥ degree + 1, knots.size() == controlCount + degree + 1, every knot finite,
// knots non-decreasing, no multiplicity above degree + 1, and x_p < x_n (non-empty domain).
// `what` prefixes the message, e.g. "knotsU".
void validateKnots(int degree, int controlCount, const std::vector<double>& knots,
                   const char* what = "knot vector");

// How many knots equal `value` exactly.
int knotMultiplicity(const std::vector<double>& knots, double value);

// The span μ ∈ [p, n-1] with x_μ ≤ t < x_{μ+1}, the interval whose p + 1 basis functions
// N_{μ-p..μ} are the only nonzero ones at t. Right-end convention: at t = x_n (and beyond)
// the answer is the last non-empty span ending at x_n, so the domain is closed on the right
// and the curve reaches its end point. Before x_p the first non-empty span is returned
// (polynomial extension). n = knots.size() - p - 1; the knots must be valid.
// Throws std::invalid_argument for non-finite t.
int findSpan(int degree, const std::vector<double>& knots, double t);

}  // namespace tessera
