#include "mesh/lower_bound.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "common/parallel_for.h"
#include "common/stopwatch.h"
#include "geometry/bezier.h"
#include "geometry/rational.h"
#include "geometry/surface_normal.h"

namespace tessera {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct GaussRule {
  std::vector<double> nodes, weights;  // on [0, 1]
};

// The n-point Gauss–Legendre rule on [0, 1]: the roots of P_n by Newton's method from
// Tricomi's estimate cos(π(i − ¼)/(n + ½)), weights 2/((1 − x²) P_n'(x)²), halved for [0, 1].
GaussRule gaussLegendre(int n) {
  GaussRule rule;
  for (int i = 1; i <= n; ++i) {
    double x = std::cos(kPi * (i - 0.25) / (n + 0.5)), derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double previous = 1.0, current = x;  // P_0, P_1
      for (int j = 2; j <= n; ++j) {
        const double next = ((2 * j - 1) * x * current - (j - 1) * previous) / j;
        previous = current;
        current = next;
      }
      derivative = n * (x * current - previous) / (x * x - 1.0);
      const double step = current / derivative;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    rule.nodes.push_back(0.5 * (1.0 - x));
    rule.weights.push_back(1.0 / ((1.0 - x * x) * derivative * derivative));
  }
  return rule;
}

// √|LN − M²| at (u, v) with the unit normal of docs/conventions.md (the limiting one where
// Su × Sv vanishes), signed by K: √|K|·|Su × Sv|, so du dv integrates it to √|K| dA.
double signedCurvatureRoot(const SurfaceDerivatives& d, double u, double v, double length) {
  const glm::dvec3 n = unitNormal(d, u, v, length);
  const double L = glm::dot(d.puu, n), M = glm::dot(d.puv, n), N = glm::dot(d.pvv, n);
  const double det = L * N - M * M;
  return det >= 0.0 ? std::sqrt(det) : -std::sqrt(-det);
}

void validateOptions(double tolerance, const LowerBoundOptions& options) {
  if (!(std::isfinite(tolerance) && tolerance > 0.0))
    throw std::invalid_argument("asymptoticTriangleLowerBound: tolerance must be finite and > 0, "
                                "got " + std::to_string(tolerance));
  if (options.points < 1 || options.points > 32)
    throw std::invalid_argument("asymptoticTriangleLowerBound: points must be 1..32, got " +
                                std::to_string(options.points));
  if (options.maxCells < 1 || options.maxCells > 4096)
    throw std::invalid_argument("asymptoticTriangleLowerBound: maxCells must be 1..4096, got " +
                                std::to_string(options.maxCells));
  if (!(options.relativeChange > 0.0))
    throw std::invalid_argument("asymptoticTriangleLowerBound: relativeChange must be > 0");
}

// A polynomial patch, or a rational one with one weight per control point.
void validateWeightedPatch(const BezierPatch& patch, const char* where) {
  if (patch.weights.empty()) return validatePatch(patch);
  if (patch.weights.size() != patch.cp.size())
    throw std::invalid_argument(std::string(where) + ": " + std::to_string(patch.weights.size()) +
                                " weights for " + std::to_string(patch.cp.size()) +
                                " control points");
  validateRationalPatch(toRationalPatch(patch));
}

}  // namespace

CurvatureRootIntegral integrateCurvatureRoot(const BezierPatch& patch, int cells, int points) {
  if (cells < 1 || points < 1 || points > 32)
    throw std::invalid_argument("integrateCurvatureRoot: need cells ≥ 1 and 1 ≤ points ≤ 32");
  const bool rational = !patch.weights.empty();
  validateWeightedPatch(patch, "integrateCurvatureRoot");
  const RationalBezierPatch homogeneous = rational ? toRationalPatch(patch) : RationalBezierPatch{};
  const double length = rational ? controlNetDiagonal(homogeneous) : controlNetDiagonal(patch);
  const GaussRule rule = gaussLegendre(points);
  const double h = 1.0 / cells;
  CurvatureRootIntegral sum;
  for (int ci = 0; ci < cells; ++ci)
    for (int cj = 0; cj < cells; ++cj)
      for (int a = 0; a < points; ++a)
        for (int b = 0; b < points; ++b) {
          const double u = (ci + rule.nodes[a]) * h, v = (cj + rule.nodes[b]) * h;
          const SurfaceDerivatives d = rational ? rationalPatchDerivatives(homogeneous, u, v)
                                                : patchDerivatives(patch, u, v);
          const double value = signedCurvatureRoot(d, u, v, length);
          const double weight = rule.weights[a] * rule.weights[b] * h * h;
          (value > 0.0 ? sum.positive : sum.negative) += weight * std::abs(value);
        }
  return sum;
}

double lowerBoundTriangles(const CurvatureRootIntegral& integral, double tolerance) {
  return (kEllipticTriangleDensity * integral.positive +
          kHyperbolicTriangleDensity * integral.negative) /
         tolerance;
}

TriangleLowerBound asymptoticTriangleLowerBound(const std::vector<BezierPatch>& patches,
                                                double tolerance,
                                                const LowerBoundOptions& options) {
  validateOptions(tolerance, options);
  const Stopwatch stopwatch;
  // ∫√|K| dA is a length. Changes below 1e-12 of the nets' total size are rounding (a plane's
  // integrand is 0 up to it), not a lack of convergence.
  double size = 0.0;
  for (const BezierPatch& patch : patches) {
    validateWeightedPatch(patch, "asymptoticTriangleLowerBound");
    size += patch.weights.empty() ? controlNetDiagonal(patch)
                                  : controlNetDiagonal(toRationalPatch(patch));
  }
  const double floor = 1e-12 * size / tolerance;
  TriangleLowerBound bound;
  bound.tolerance = tolerance;
  for (int cells = 1; cells <= options.maxCells; cells *= 2) {
    LowerBoundStep step;
    step.cells = cells;
    // Patches on all threads; summed in input order, so the result does not depend on them.
    std::vector<CurvatureRootIntegral> perPatch(patches.size());
    parallelFor(patches.size(), options.threads, [&](size_t begin, size_t end) {
      for (size_t p = begin; p < end; ++p)
        perPatch[p] = integrateCurvatureRoot(patches[p], cells, options.points);
    });
    for (const CurvatureRootIntegral& one : perPatch) {
      step.integral.positive += one.positive;
      step.integral.negative += one.negative;
    }
    step.triangles = lowerBoundTriangles(step.integral, tolerance);
    bound.refinement.push_back(step);
    if (bound.refinement.size() >= 2) {
      const double before = bound.refinement[bound.refinement.size() - 2].triangles;
      const double change = std::abs(step.triangles - before);
      if (change <= options.relativeChange * step.triangles || change <= floor) {
        bound.converged = true;
        break;
      }
    }
  }
  const LowerBoundStep& last = bound.refinement.back();
  bound.cells = last.cells;
  bound.integral = last.integral;
  bound.positive = kEllipticTriangleDensity * last.integral.positive / tolerance;
  bound.negative = kHyperbolicTriangleDensity * last.integral.negative / tolerance;
  bound.triangles = bound.positive + bound.negative;
  bound.ms = stopwatch.elapsedMs();
  return bound;
}

}  // namespace tessera
