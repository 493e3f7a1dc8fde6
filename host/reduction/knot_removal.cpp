#include "reduction/knot_removal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>

#include "bspline/knots.h"
#include "common/stopwatch.h"
#include "reduction/detail/order.h"

namespace tessera {

namespace {

const std::vector<double>& knotsOf(const BSplineSurface& s, ParamDirection d) {
  return d == ParamDirection::U ? s.knotsU : s.knotsV;
}
int degreeOf(const BSplineSurface& s, ParamDirection d) {
  return d == ParamDirection::U ? s.degreeU : s.degreeV;
}
int countOf(const BSplineSurface& s, ParamDirection d) {
  return d == ParamDirection::U ? s.countU : s.countV;
}

void validateFinite(const std::vector<glm::dvec3>& cp, const char* what) {
  for (size_t k = 0; k < cp.size(); ++k) {
    if (!std::isfinite(cp[k].x) || !std::isfinite(cp[k].y) || !std::isfinite(cp[k].z)) {
      throw std::invalid_argument(std::string(what) + ": control point " + std::to_string(k) +
                                  " is not finite");
    }
  }
}

}  // namespace

const char* stopReasonName(StopReason reason) {
  switch (reason) {
    case StopReason::Threshold: return "threshold";
    case StopReason::MinimumControlPoints: return "minimum control points";
  }
  return "?";
}

const char* knotChoiceName(KnotChoice choice) {
  switch (choice) {
    case KnotChoice::Curvature: return "curvature";
    case KnotChoice::CurvatureFixed: return "curv-fixed";
    case KnotChoice::CurvatureSweeps: return "curv-sweeps";
    case KnotChoice::Random: return "random";
  }
  return "?";
}

const char* directionName(ParamDirection direction) {
  return direction == ParamDirection::U ? "u" : "v";
}

Eigen::MatrixXd pseudoInverse(const Eigen::MatrixXd& a) {
  if (a.size() == 0) return Eigen::MatrixXd(a.cols(), a.rows());
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& sigma = svd.singularValues();
  const double cutoff = static_cast<double>(std::max(a.rows(), a.cols())) *
                        std::numeric_limits<double>::epsilon() * sigma(0);
  Eigen::VectorXd inverse = sigma;
  for (Eigen::Index k = 0; k < sigma.size(); ++k) inverse(k) = sigma(k) > cutoff ? 1.0 / sigma(k) : 0.0;
  return svd.matrixV() * inverse.asDiagonal() * svd.matrixU().transpose();
}

std::vector<glm::dvec3> inverseOslo(int degree, const std::vector<double>& coarseKnots,
                                    const std::vector<double>& fineKnots,
                                    const std::vector<glm::dvec3>& fineCp) {
  const int fineCount = static_cast<int>(fineKnots.size()) - degree - 1;
  if (static_cast<int>(fineCp.size()) != fineCount) {
    throw std::invalid_argument("inverseOslo: " + std::to_string(fineCp.size()) +
                                " control points for " + std::to_string(fineKnots.size()) +
                                " fine knots of degree " + std::to_string(degree) +
                                " (expected " + std::to_string(fineCount) + ")");
  }
  validateFinite(fineCp, "inverseOslo");
  return applyToControlPoints(pseudoInverse(osloMatrix(degree, coarseKnots, fineKnots)), fineCp);
}

void validateReductionOptions(const ReductionOptions& o) {
  if (!std::isfinite(o.threshold) || o.threshold < 0.0) {
    throw std::invalid_argument("reduction: threshold must be finite and >= 0, got " +
                                std::to_string(o.threshold));
  }
  if (!(o.firstPassShare > 0.0 && o.firstPassShare <= 1.0)) {
    throw std::invalid_argument("reduction: first-pass share must be in (0, 1], got " +
                                std::to_string(o.firstPassShare));
  }
  if (o.minWindow < 1 || !(o.windowTolerance > 0.0) || !std::isfinite(o.windowTolerance) ||
      o.threads < 0) {
    throw std::invalid_argument("reduction: window settings must be positive");
  }
}

void validateSurfaceForReduction(const BSplineSurface& surface) {
  validateSurface(surface);
  validateFinite(surface.cp, "B-spline surface");
}

void recordAttempt(PassReport& report, int pass, int removable, bool removed, double measured,
                   const ReductionOptions& options) {
  if (removed) {
    ++report.removed;
  } else {
    report.refusedError = report.refused == 0 ? measured : std::min(report.refusedError, measured);
    ++report.refused;
    report.stop = StopReason::Threshold;
  }
  if (options.progress) {
    options.progress({pass, report.direction, report.removed, report.removed + report.refused,
                      removable, measured, report.target});
  }
}

namespace {

// κ·|C′|^power at every interior knot, combined over the curves of `d` (power 0: curvature,
// 2: normal acceleration).
std::vector<double> knotBendingPower(const BSplineSurface& s, ParamDirection d,
                                     CurvatureAggregate aggregate, int power) {
  validateSurface(s);
  const int p = degreeOf(s, d);
  const std::vector<double>& y = knotsOf(s, d);
  const int count = countOf(s, d);
  const int curves = d == ParamDirection::U ? s.countV : s.countU;
  const auto point = [&](int curve, int k) -> const glm::dvec3& {
    return d == ParamDirection::U ? s.at(k, curve) : s.at(curve, k);
  };
  std::vector<double> score(y.size(), 0.0);
  for (int k = p + 1; k < count; ++k) {
    const double t = y[static_cast<size_t>(k)];
    // The basis derivatives depend only on the knots: once per knot, shared by every curve.
    const int span = findSpan(p, y, t);
    const BasisTable basis = basisDerivatives(span, p, y, t, 2);
    double combined = 0.0;
    for (int c = 0; c < curves; ++c) {
      glm::dvec3 d1(0.0), d2(0.0);
      for (int r = 0; r <= p; ++r) {
        const glm::dvec3& q = point(c, span - p + r);
        d1 += basis[1][static_cast<size_t>(r)] * q;
        d2 += basis[2][static_cast<size_t>(r)] * q;
      }
      const double speed = glm::length(d1);
      const double divisor = power == 0 ? speed * speed * speed : speed;
      const double kappa = speed > 0.0 ? glm::length(glm::cross(d1, d2)) / divisor : 0.0;
      combined = aggregate == CurvatureAggregate::Max ? std::max(combined, kappa)
                                                      : combined + kappa;
    }
    score[static_cast<size_t>(k)] =
        aggregate == CurvatureAggregate::Max ? combined : combined / curves;
  }
  return score;
}

}  // namespace

std::vector<double> knotCurvature(const BSplineSurface& s, ParamDirection d,
                                  CurvatureAggregate aggregate) {
  return knotBendingPower(s, d, aggregate, 0);
}

std::vector<double> knotBending(const BSplineSurface& s, ParamDirection d,
                                CurvatureAggregate aggregate) {
  return knotBendingPower(s, d, aggregate, 2);
}

std::vector<int> removalOrder(const BSplineSurface& s, ParamDirection d,
                              const ReductionOptions& options) {
  const int p = degreeOf(s, d);
  const int count = countOf(s, d);
  std::vector<int> order;
  for (int k = p + 1; k < count; ++k) order.push_back(k);
  if (options.choice == KnotChoice::Random) {
    // Fisher–Yates with an explicit draw, so the order is the same with every standard library.
    // u and v draw from different streams (seed, seed + 1), or a square net would lose the
    // same knot positions in both directions.
    std::mt19937_64 rng(options.seed + (d == ParamDirection::U ? 0 : 1));
    for (size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[rng() % i]);
    return order;
  }
  const std::vector<double> score = knotCurvature(s, d, options.aggregate);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return score[static_cast<size_t>(a)] < score[static_cast<size_t>(b)];
  });
  return order;
}

DeviationStats netDeviation(const BSplineSurface& original, const BSplineSurface& reduced) {
  if (original.degreeU != reduced.degreeU || original.degreeV != reduced.degreeV) {
    throw std::invalid_argument("netDeviation: the surfaces have different degrees");
  }
  BSplineSurface refined = refineSurface(reduced, ParamDirection::U, original.knotsU);
  refined = refineSurface(refined, ParamDirection::V, original.knotsV);
  DeviationStats stats;
  for (size_t k = 0; k < original.cp.size(); ++k) {
    const double distance = glm::length(refined.cp[k] - original.cp[k]);
    stats.mean += distance;
    stats.max = std::max(stats.max, distance);
  }
  if (!original.cp.empty()) stats.mean /= static_cast<double>(original.cp.size());
  return stats;
}

ReductionResult reduceSurfaceReference(const BSplineSurface& original,
                                       const ReductionOptions& options) {
  validateReductionOptions(options);
  validateSurfaceForReduction(original);
  ReductionResult result;
  result.surface = original;
  result.originalControlPoints = static_cast<long long>(original.cp.size());
  const ParamDirection dirs[2] = {options.firstDirection,
                                  options.firstDirection == ParamDirection::U ? ParamDirection::V
                                                                              : ParamDirection::U};
  for (int pass = 0; pass < 2; ++pass) {
    const Stopwatch stopwatch;
    const ParamDirection dir = dirs[pass];
    PassReport& report = result.passes[pass];
    report.direction = dir;
    report.target = pass == 0 ? options.firstPassShare * options.threshold : options.threshold;
    const int p = degreeOf(original, dir);
    const std::vector<double>& y = knotsOf(original, dir);
    // The least-squares data of this pass: the surface as the previous pass left it, whose
    // knots in `dir` are still the original ones.
    const BSplineSurface data = result.surface;
    report.originalCount = countOf(data, dir);
    report.error = netDeviation(original, data);
    KnotSchedule schedule(original, dir, options);
    std::vector<bool> present(y.size(), true);
    report.stop = StopReason::MinimumControlPoints;
    for (int knot = schedule.next(); knot >= 0; knot = schedule.next()) {
      present[static_cast<size_t>(knot)] = false;
      std::vector<double> x;
      for (size_t k = 0; k < y.size(); ++k) {
        if (present[k]) x.push_back(y[k]);
      }
      // One A⁺ for every curve of the direction: one product over all rows of the net.
      const Eigen::MatrixXd inverse = pseudoInverse(osloMatrix(p, x, y));
      BSplineSurface candidate = data;
      candidate.cp = applyToNet(inverse, data.cp, data.countU, data.countV, dir);
      if (dir == ParamDirection::U) {
        candidate.knotsU = x;
        candidate.countU = static_cast<int>(inverse.rows());
      } else {
        candidate.knotsV = x;
        candidate.countV = static_cast<int>(inverse.rows());
      }
      const DeviationStats error = netDeviation(original, candidate);
      const bool accepted = error.value(options.measure) <= report.target;
      schedule.record(knot, accepted);
      recordAttempt(report, pass, schedule.size(), accepted, error.value(options.measure),
                    options);
      if (!accepted) {
        present[static_cast<size_t>(knot)] = true;  // refused: the knot stays, try the next
        continue;
      }
      result.surface = std::move(candidate);
      report.error = error;
    }
    report.keptCount = countOf(result.surface, dir);
    report.seconds = stopwatch.elapsedSeconds();
  }
  result.error = result.passes[1].error;
  result.keptControlPoints = static_cast<long long>(result.surface.cp.size());
  return result;
}

}  // namespace tessera
