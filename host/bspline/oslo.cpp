#include "bspline/oslo.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

#include "bspline/knots.h"

namespace tessera {

namespace {

double ratioOrZero(double num, double den) { return den == 0.0 ? 0.0 : num / den; }

}  // namespace

bool knotsContain(const std::vector<double>& y, const std::vector<double>& x) {
  size_t k = 0;  // one merge walk
  for (double v : y) {
    if (k < x.size() && x[k] == v) ++k;
  }
  return k == x.size();
}

int osloRow(int degree, const std::vector<double>& x, const std::vector<double>& y, int j,
            double* values) {
  const int p = degree;
  const int n = static_cast<int>(x.size()) - p - 1;
  const int lastKnot = n + p;
  const auto xi = [&](int i) { return x[static_cast<size_t>(i)]; };
  const double yj = y[static_cast<size_t>(j)];
  // Base case α_{i,0}(j) = 1 iff x_i ≤ y_j < x_{i+1}. Half-open: Hayashimoto et al. print
  // ≤ on both sides, which would count a y_j that equals a knot in two intervals.
  const int mu = static_cast<int>(std::upper_bound(x.begin(), x.end(), yj) - x.begin()) - 1;
  // alpha[i − (mu − p)] holds α_{i,r}(j) for i ∈ [mu − r, mu].
  std::array<double, kMaxDegree + 2> alpha{};
  alpha[static_cast<size_t>(p)] = 1.0;
  // Level r is the paper's order k = r + 1, whose new knot is y_{j+k-1} = y_{j+r}.
  for (int r = 1; r <= p; ++r) {
    const double t = y[static_cast<size_t>(j + r)];
    for (int i = mu - r; i <= mu; ++i) {
      const size_t slot = static_cast<size_t>(i - (mu - p));
      // α_{i,r} needs x_i … x_{i+r+1}. Outside the vector these are B-splines that do not
      // exist, and they only ever feed other non-existent ones (i < 0 feeds lower i; past
      // the end feeds i' with i' + r' + 1 past the end too): 0 changes nothing real.
      if (i < 0 || i + r + 1 > lastKnot) {
        alpha[slot] = 0.0;
        continue;
      }
      // Ascending i reads alpha[slot + 1] (level r − 1) before it is overwritten.
      alpha[slot] = ratioOrZero(t - xi(i), xi(i + r) - xi(i)) * alpha[slot] +
                    ratioOrZero(xi(i + r + 1) - t, xi(i + r + 1) - xi(i + 1)) * alpha[slot + 1];
    }
  }
  // The nonzeros lie in [max(mu − p, 0), min(mu, n − 1)]: a window of p + 1 columns starting at
  // mu − p clamped into [0, n − p − 1] holds them all.
  const int first = std::clamp(mu - p, 0, n - p - 1);
  for (int r = 0; r <= p; ++r) {
    const int i = first + r;
    values[r] = (i >= mu - p && i <= mu) ? alpha[static_cast<size_t>(i - (mu - p))] : 0.0;
  }
  return first;
}

std::vector<double> mergeKnots(const std::vector<double>& knots, std::vector<double> inserted) {
  inserted.insert(inserted.end(), knots.begin(), knots.end());
  std::sort(inserted.begin(), inserted.end());
  return inserted;
}

void validateOsloKnots(int degree, const std::vector<double>& x, const std::vector<double>& y) {
  const int p = degree;
  validateKnots(p, static_cast<int>(x.size()) - p - 1, x, "osloMatrix old knots");
  validateKnots(p, static_cast<int>(y.size()) - p - 1, y, "osloMatrix new knots");
  if (!knotsContain(y, x)) {
    throw std::invalid_argument("osloMatrix: new knots do not contain every old knot");
  }
  if (y.front() != x.front() || y.back() != x.back()) {
    throw std::invalid_argument("osloMatrix: new knots reach outside [x_0, x_last]");
  }
}

Eigen::MatrixXd osloMatrix(int degree, const std::vector<double>& x, const std::vector<double>& y) {
  const int p = degree;
  const int n = static_cast<int>(x.size()) - p - 1;
  const int m = static_cast<int>(y.size()) - p - 1;
  validateOsloKnots(p, x, y);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(m, n);
  std::array<double, kMaxDegree + 1> row{};
  for (int j = 0; j < m; ++j) {
    const int first = osloRow(p, x, y, j, row.data());
    for (int r = 0; r <= p; ++r) a(j, first + r) = row[static_cast<size_t>(r)];
  }
  return a;
}

std::vector<glm::dvec3> applyToControlPoints(const Eigen::MatrixXd& m,
                                             const std::vector<glm::dvec3>& cp) {
  if (m.cols() != static_cast<Eigen::Index>(cp.size())) {
    throw std::invalid_argument("applyToControlPoints: matrix has " + std::to_string(m.cols()) +
                                " columns for " + std::to_string(cp.size()) + " control points");
  }
  std::vector<glm::dvec3> out(static_cast<size_t>(m.rows()), glm::dvec3(0.0));
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    for (Eigen::Index c = 0; c < m.cols(); ++c) {
      if (m(r, c) != 0.0) out[static_cast<size_t>(r)] += m(r, c) * cp[static_cast<size_t>(c)];
    }
  }
  return out;
}

std::vector<glm::dvec3> applyToNet(const Eigen::MatrixXd& m, const std::vector<glm::dvec3>& cp,
                                   int countU, int countV, ParamDirection direction) {
  const bool alongU = direction == ParamDirection::U;
  if (countU < 0 || countV < 0 ||
      cp.size() != static_cast<size_t>(countU) * static_cast<size_t>(countV) ||
      m.cols() != (alongU ? countU : countV)) {
    throw std::invalid_argument("applyToNet: a " + std::to_string(m.rows()) + " x " +
                                std::to_string(m.cols()) + " matrix does not fit a " +
                                std::to_string(countU) + " x " + std::to_string(countV) +
                                " net along " + (alongU ? "u" : "v"));
  }
  const int rows = static_cast<int>(m.rows());
  const int outU = alongU ? rows : countU;
  const int outV = alongU ? countV : rows;
  std::vector<glm::dvec3> out(static_cast<size_t>(outU) * static_cast<size_t>(outV),
                              glm::dvec3(0.0));
  const auto in = [&](int i, int j) -> const glm::dvec3& {
    return cp[static_cast<size_t>(i) * static_cast<size_t>(countV) + static_cast<size_t>(j)];
  };
  const auto at = [&](int i, int j) -> glm::dvec3& {
    return out[static_cast<size_t>(i) * static_cast<size_t>(outV) + static_cast<size_t>(j)];
  };
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < static_cast<int>(m.cols()); ++c) {
      const double w = m(r, c);
      if (w == 0.0) continue;
      if (alongU) {
        for (int j = 0; j < countV; ++j) at(r, j) += w * in(c, j);
      } else {
        for (int i = 0; i < countU; ++i) at(i, r) += w * in(i, c);
      }
    }
  }
  return out;
}

BSplineCurve refineCurve(const BSplineCurve& curve, const std::vector<double>& newKnots) {
  validateCurve(curve);
  const Eigen::MatrixXd a = osloMatrix(curve.degree, curve.knots, newKnots);
  return BSplineCurve{curve.degree, newKnots, applyToControlPoints(a, curve.cp)};
}

BSplineSurface refineSurface(const BSplineSurface& surface, ParamDirection direction,
                             const std::vector<double>& newKnots) {
  validateSurface(surface);
  BSplineSurface out = surface;
  const bool alongU = direction == ParamDirection::U;
  const Eigen::MatrixXd a = alongU ? osloMatrix(surface.degreeU, surface.knotsU, newKnots)
                                   : osloMatrix(surface.degreeV, surface.knotsV, newKnots);
  out.cp = applyToNet(a, surface.cp, surface.countU, surface.countV, direction);
  if (alongU) {
    out.knotsU = newKnots;
    out.countU = static_cast<int>(a.rows());
  } else {
    out.knotsV = newKnots;
    out.countV = static_cast<int>(a.rows());
  }
  return out;
}

BSplineCurve insertKnot(const BSplineCurve& curve, double t) {
  validateCurve(curve);
  const int p = curve.degree;
  const std::vector<double>& x = curve.knots;
  const int n = static_cast<int>(curve.cp.size());
  if (!(t >= x[static_cast<size_t>(p)] && t <= x[static_cast<size_t>(n)])) {
    throw std::invalid_argument("insertKnot: t = " + std::to_string(t) +
                                " is outside the domain [x_p, x_n]");
  }
  if (knotMultiplicity(x, t) >= p + 1) {
    throw std::invalid_argument("insertKnot: knot " + std::to_string(t) +
                                " already has multiplicity degree + 1");
  }
  // On the non-empty span μ ∋ t only Q_{μ−p+1..μ} change: each new point lies on the leg
  // Q_{i−1}Q_i at the ratio of t within [x_i, x_{i+p}] (never empty: it contains the span).
  const int mu = findSpan(p, x, t);
  BSplineCurve out{p, mergeKnots(x, {t}), {}};
  out.cp.reserve(static_cast<size_t>(n + 1));
  for (int i = 0; i <= n; ++i) {
    if (i <= mu - p) {
      out.cp.push_back(curve.cp[static_cast<size_t>(i)]);
    } else if (i > mu) {
      out.cp.push_back(curve.cp[static_cast<size_t>(i - 1)]);
    } else {
      const double ratio = (t - x[static_cast<size_t>(i)]) /
                           (x[static_cast<size_t>(i + p)] - x[static_cast<size_t>(i)]);
      out.cp.push_back((1.0 - ratio) * curve.cp[static_cast<size_t>(i - 1)] +
                       ratio * curve.cp[static_cast<size_t>(i)]);
    }
  }
  return out;
}

}  // namespace tessera
