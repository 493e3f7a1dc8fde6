#include "reduction/fast.h"

#include <algorithm>
#include <cmath>

#include "common/stopwatch.h"
#include "reduction/detail/order.h"
#include "reduction/detail/pass.h"

namespace tessera {

namespace {

ParamDirection otherDirection(ParamDirection d) {
  return d == ParamDirection::U ? ParamDirection::V : ParamDirection::U;
}

// The net as the curves of `dir` see it: fine index of `dir` major, then the points of the
// other direction, then xyz. Along u that is the net's own order; along v its transpose.
std::vector<double> toPassLayout(const BSplineSurface& s, ParamDirection dir) {
  std::vector<double> out(s.cp.size() * 3);
  for (int i = 0; i < s.countU; ++i) {
    for (int j = 0; j < s.countV; ++j) {
      const size_t at = dir == ParamDirection::U ? static_cast<size_t>(i) * s.countV + j
                                                 : static_cast<size_t>(j) * s.countU + i;
      const glm::dvec3& q = s.at(i, j);
      out[3 * at] = q.x;
      out[3 * at + 1] = q.y;
      out[3 * at + 2] = q.z;
    }
  }
  return out;
}

// The inverse of toPassLayout for a net with `count` points along `dir`.
void fromPassLayout(const std::vector<double>& q, ParamDirection dir, int count,
                    BSplineSurface& s) {
  (dir == ParamDirection::U ? s.countU : s.countV) = count;
  s.cp.resize(static_cast<size_t>(s.countU) * static_cast<size_t>(s.countV));
  for (int i = 0; i < s.countU; ++i) {
    for (int j = 0; j < s.countV; ++j) {
      const size_t at = dir == ParamDirection::U ? static_cast<size_t>(i) * s.countV + j
                                                 : static_cast<size_t>(j) * s.countU + i;
      s.at(i, j) = {q[3 * at], q[3 * at + 1], q[3 * at + 2]};
    }
  }
}

// The final net of a pass from scratch: Q = A⁺·data, by the banded solve or by the explicit
// A⁺ on a CurveProduct backend.
std::vector<double> finalNet(const BandMatrix& a, int p, const std::vector<double>& data,
                             int columns, CurveProduct* product) {
  if (product == nullptr) return bandedLeastSquares(a, p, data.data(), columns);
  const int curves = columns / 3;
  const size_t m = static_cast<size_t>(a.rows), n = static_cast<size_t>(a.cols);
  std::vector<glm::dvec3> in(static_cast<size_t>(curves) * m);
  for (size_t j = 0; j < m; ++j) {
    for (size_t c = 0; c < static_cast<size_t>(curves); ++c) {
      const double* q = &data[(j * curves + c) * 3];
      in[c * m + j] = {q[0], q[1], q[2]};
    }
  }
  // 1e-10: far below fp32 (2⁻²⁴ ≈ 6e-8), and the rows decay fast enough that what is cut
  // sums to about the same.
  const std::vector<glm::dvec3> out = product->apply(pseudoInverseBand(a, p, 1e-10), in, curves);
  std::vector<double> q(n * static_cast<size_t>(columns));
  for (size_t i = 0; i < n; ++i) {
    for (size_t c = 0; c < static_cast<size_t>(curves); ++c) {
      const glm::dvec3& v = out[c * n + i];
      double* dst = &q[(i * curves + c) * 3];
      dst[0] = v.x;
      dst[1] = v.y;
      dst[2] = v.z;
    }
  }
  return q;
}

// (A·Q)'s fine rows, m × columns.
std::vector<double> refineRows(const BandMatrix& a, const std::vector<double>& q, int columns) {
  const size_t k = static_cast<size_t>(columns);
  std::vector<double> out(static_cast<size_t>(a.rows) * k, 0.0);
  for (int j = 0; j < a.rows; ++j) {
    const double* v = a.values.data() + a.offset[static_cast<size_t>(j)];
    double* dst = out.data() + static_cast<size_t>(j) * k;
    for (int s = 0; s < a.width(j); ++s) {
      const double* src = q.data() + static_cast<size_t>(a.first[static_cast<size_t>(j)] + s) * k;
      for (size_t c = 0; c < k; ++c) dst[c] += v[s] * src[c];
    }
  }
  return out;
}

}  // namespace

ReductionResult reduceSurface(const BSplineSurface& original, const ReductionOptions& options,
                              CurveProduct* product, FastPathStats* stats) {
  validateReductionOptions(options);
  validateSurfaceForReduction(original);
  FastPathStats ownStats;
  FastPathStats& st = stats != nullptr ? *stats : ownStats;
  ReductionResult result;
  result.surface = original;
  result.originalControlPoints = static_cast<long long>(original.cp.size());
  const ParamDirection dirs[2] = {options.firstDirection, otherDirection(options.firstDirection)};
  for (int pass = 0; pass < 2; ++pass) {
    const Stopwatch stopwatch;
    const ParamDirection dir = dirs[pass];
    const bool alongU = dir == ParamDirection::U;
    PassReport& report = result.passes[pass];
    report.direction = dir;
    report.target = pass == 0 ? options.firstPassShare * options.threshold : options.threshold;
    const int p = alongU ? original.degreeU : original.degreeV;
    const std::vector<double>& y = alongU ? original.knotsU : original.knotsV;
    BSplineSurface& current = result.surface;
    const std::vector<double> data = toPassLayout(current, dir);
    const int columns = 3 * (alongU ? current.countV : current.countU);
    // The original in this pass's layout: the data itself in the first pass.
    std::vector<double> originalLayout;
    BandMatrix refine;
    SlabError error{data.data(), columns / 3, nullptr};
    if (pass == 1) {
      originalLayout = toPassLayout(original, dir);
      refine = alongU ? osloBand(original.degreeV, current.knotsV, original.knotsV)
                      : osloBand(original.degreeU, current.knotsU, original.knotsU);
      error = {originalLayout.data(), refine.rows, &refine};
    }
    ReductionPass engine(p, y, data.data(), columns, error, options, st);
    report.originalCount = engine.controlCount();
    report.error = engine.error();
    KnotSchedule schedule(original, dir, options);
    report.stop = StopReason::MinimumControlPoints;
    for (int knot = schedule.next(); knot >= 0; knot = schedule.next()) {
      double measured = 0.0;
      const bool removed = engine.tryRemove(knot, options.measure, report.target, &measured);
      schedule.record(knot, removed);
      recordAttempt(report, pass, schedule.size(), removed, measured, options);
    }
    st.searchSeconds[pass] = stopwatch.elapsedSeconds();

    const Stopwatch productStopwatch;
    const BandMatrix a = osloBand(p, engine.knots(), y);
    const std::vector<double> q = finalNet(a, p, data, columns, product);
    st.productSeconds[pass] = productStopwatch.elapsedSeconds();
    const std::vector<double> kept = engine.net();
    double drift = 0.0;
    for (size_t i = 0; i < q.size(); ++i) drift = std::max(drift, std::abs(q[i] - kept[i]));
    st.drift[pass] = drift;

    // The reported error is that of the final net, measured the same way as during the search.
    const std::vector<double> rows = refineRows(a, q, columns);
    std::vector<double> sum(static_cast<size_t>(a.rows)), max(static_cast<size_t>(a.rows));
    error.measure(0, a.rows, rows.data(), columns, sum.data(), max.data());
    report.error.mean = 0.0;
    for (double s : sum) report.error.mean += s;
    report.error.mean /= static_cast<double>(a.rows) * error.others;
    report.error.max = *std::max_element(max.begin(), max.end());

    (alongU ? current.knotsU : current.knotsV) = engine.knots();
    fromPassLayout(q, dir, a.cols, current);
    report.keptCount = a.cols;
    report.seconds = stopwatch.elapsedSeconds();
  }
  result.error = result.passes[1].error;
  result.keptControlPoints = static_cast<long long>(result.surface.cp.size());
  return result;
}

}  // namespace tessera
