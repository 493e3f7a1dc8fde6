#include "reduction/detail/pass.h"

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <cstring>

#include "bspline/oslo.h"
#include "common/parallel_for.h"

namespace tessera {

void SlabError::measure(int ja, int jb, const double* p, int columns, double* sum,
                        double* max) const {
  for (int j = ja; j < jb; ++j) {
    const double* row = p + static_cast<size_t>(j - ja) * static_cast<size_t>(columns);
    const double* orig = original + static_cast<size_t>(j) * static_cast<size_t>(others) * 3;
    double s = 0.0, largest = 0.0;
    for (int o = 0; o < others; ++o) {
      double x, y, z;
      if (refine == nullptr) {
        x = row[3 * o];
        y = row[3 * o + 1];
        z = row[3 * o + 2];
      } else {
        x = y = z = 0.0;
        const double* w = refine->values.data() + refine->offset[static_cast<size_t>(o)];
        const double* src = row + 3 * refine->first[static_cast<size_t>(o)];
        for (int t = 0; t < refine->width(o); ++t) {
          x += w[t] * src[3 * t];
          y += w[t] * src[3 * t + 1];
          z += w[t] * src[3 * t + 2];
        }
      }
      const double dx = x - orig[3 * o], dy = y - orig[3 * o + 1], dz = z - orig[3 * o + 2];
      const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
      s += d;
      largest = std::max(largest, d);
    }
    sum[j - ja] = s;
    max[j - ja] = largest;
  }
}

ReductionPass::ReductionPass(int degree, const std::vector<double>& fineKnots, const double* data,
                             int columns, const SlabError& error, const ReductionOptions& options,
                             FastPathStats& stats)
    : p_(degree),
      m_(static_cast<int>(fineKnots.size()) - degree - 1),
      columns_(columns),
      y_(fineKnots),
      data_(data),
      error_(error),
      stats_(stats),
      minWindow_(std::max(options.minWindow, degree + 1)),
      window_(minWindow_),
      threads_(options.threads > 0 ? options.threads : static_cast<int>(resolveThreadCount(0))),
      x_(fineKnots) {
  residual_.resize(static_cast<size_t>(threads_));
  const size_t k = static_cast<size_t>(columns_);
  const size_t count = static_cast<size_t>(m_) * k;
  double scale = 1.0;
  for (size_t i = 0; i < count; ++i) scale = std::max(scale, std::abs(data[i]));
  tolerance_ = options.windowTolerance * scale;
  pointCount_ = static_cast<double>(m_) * error.others;
  pool_.assign(data, data + count);
  for (int i = 0; i < m_; ++i) {
    qRow_.push_back(pool_.data() + static_cast<size_t>(i) * k);
    fineIndex_.push_back(i);
  }
  slabSum_.resize(static_cast<size_t>(m_));
  slabMax_.resize(static_cast<size_t>(m_));
  error_.measure(0, m_, data, columns_, slabSum_.data(), slabMax_.data());
  for (double s : slabSum_) total_ += s;
}

DeviationStats ReductionPass::error() const {
  return {total_ / pointCount_, *std::max_element(slabMax_.begin(), slabMax_.end())};
}

std::vector<double> ReductionPass::net() const {
  const size_t k = static_cast<size_t>(columns_);
  std::vector<double> out(qRow_.size() * k);
  for (size_t i = 0; i < qRow_.size(); ++i) std::memcpy(&out[i * k], qRow_[i], k * sizeof(double));
  return out;
}

ReductionPass::WindowChange ReductionPass::solveWindow(int pos, int a, int b, int ja, int jb) {
  const int p = p_;
  const size_t k = static_cast<size_t>(columns_);
  const size_t band = static_cast<size_t>(p + 1);
  const int rows = jb - ja, w = b - a + 1;
  const int affectedLo = pos - p - 1, affectedHi = pos - 1;
  const int n1 = controlCount() - 1;
  const auto oldRow = [&](int col) -> const double* {
    return qRow_[static_cast<size_t>(col < pos ? col : col + 1)];
  };
  // The rows of the Oslo matrix and the normal matrix of the window: independent of the data.
  rowFirst_.resize(static_cast<size_t>(rows));
  rowValues_.resize(static_cast<size_t>(rows) * band);
  g_.assign(static_cast<size_t>(w) * band, 0.0);
  for (int r = 0; r < rows; ++r) {
    double* v = rowValues_.data() + static_cast<size_t>(r) * band;
    const int f = rowFirst_[static_cast<size_t>(r)] = osloRow(p, xNew_, y_, ja + r, v);
    for (int s = 0; s <= p; ++s) {
      if (v[s] == 0.0 || f + s < a || f + s > b) continue;
      for (int t = std::max(0, a - f); t <= s; ++t) {
        g_[static_cast<size_t>(f + s - a) * band + static_cast<size_t>(t - s + p)] += v[s] * v[t];
      }
    }
  }
  const BandCholesky cholesky = factorBand(g_, w, p);
  z_.resize(static_cast<size_t>(w) * k);
  pRows_.resize(static_cast<size_t>(rows) * k);

  // Everything below is independent per column: split the columns (whole points) among the
  // threads, and walk each share in blocks that stay in cache from right-hand side to P.
  constexpr size_t kBlock = 384;
  const int parts = static_cast<double>(rows) * static_cast<double>(k) > 2e5 ? threads_ : 1;
  // Probe columns: each side's outermost column and one p + 1 further in (or as far in as the
  // unaffected columns reach); -1 where that side is the curve's end.
  const int leftIn = std::min(a + p + 1, affectedLo - 1), rightIn = std::max(b - p - 1, affectedHi + 1);
  const std::array<int, 4> probes = {a > 0 ? a : -1, a > 0 && leftIn > a ? leftIn : -1,
                                     b < n1 - 1 ? b : -1, b < n1 - 1 && rightIn < b ? rightIn : -1};
  std::vector<std::array<double, 4>> changes(static_cast<size_t>(parts), std::array<double, 4>{});
  parallelParts(static_cast<unsigned>(parts), [&](int part) {
    const size_t points = k / 3;
    const size_t c0 = 3 * (points * static_cast<size_t>(part) / static_cast<size_t>(parts));
    const size_t c1 = 3 * (points * static_cast<size_t>(part + 1) / static_cast<size_t>(parts));
    std::vector<double>& residual = residual_[static_cast<size_t>(part)];
    residual.resize(kBlock);
    std::array<double, 4>& change = changes[static_cast<size_t>(part)];
    for (size_t s0 = c0; s0 < c1; s0 += kBlock) {
      const size_t s1 = std::min(c1, s0 + kBlock), width = s1 - s0;
      for (int i = 0; i < w; ++i)
        std::fill_n(z_.data() + static_cast<size_t>(i) * k + s0, width, 0.0);
      for (int r = 0; r < rows; ++r) {
        const double* v = rowValues_.data() + static_cast<size_t>(r) * band;
        const int f = rowFirst_[static_cast<size_t>(r)];
        // The data minus what the held columns outside the window contribute to this row.
        const double* rhs = data_ + static_cast<size_t>(ja + r) * k + s0;
        bool outside = false;
        for (int s = 0; s <= p; ++s) outside |= v[s] != 0.0 && (f + s < a || f + s > b);
        if (outside) {
          std::copy(rhs, rhs + width, residual.begin());
          for (int s = 0; s <= p; ++s) {
            if (v[s] == 0.0 || (f + s >= a && f + s <= b)) continue;
            const double* q = oldRow(f + s) + s0;
            for (size_t c = 0; c < width; ++c) residual[c] -= v[s] * q[c];
          }
          rhs = residual.data();
        }
        for (int s = 0; s <= p; ++s) {
          if (v[s] == 0.0 || f + s < a || f + s > b) continue;
          double* out = z_.data() + static_cast<size_t>(f + s - a) * k + s0;
          for (size_t c = 0; c < width; ++c) out[c] += v[s] * rhs[c];
        }
      }
      cholesky.solve(z_.data() + s0, static_cast<int>(width), k);
      for (size_t probe = 0; probe < probes.size(); ++probe) {
        if (probes[probe] < 0) continue;
        const double* q = oldRow(probes[probe]) + s0;
        const double* zc = z_.data() + static_cast<size_t>(probes[probe] - a) * k + s0;
        double& into = change[probe];
        for (size_t c = 0; c < width; ++c) into = std::max(into, std::abs(zc[c] - q[c]));
      }
      for (int r = 0; r < rows; ++r) {
        const double* v = rowValues_.data() + static_cast<size_t>(r) * band;
        const int f = rowFirst_[static_cast<size_t>(r)];
        double* out = pRows_.data() + static_cast<size_t>(r) * k + s0;
        std::fill_n(out, width, 0.0);
        for (int s = 0; s <= p; ++s) {
          if (v[s] == 0.0) continue;
          const int col = f + s;
          const double* q = (col >= a && col <= b ? z_.data() + static_cast<size_t>(col - a) * k
                                                  : oldRow(col)) + s0;
          for (size_t c = 0; c < width; ++c) out[c] += v[s] * q[c];
        }
      }
    }
  });
  std::array<double, 4> largest{};
  for (const auto& c : changes) {
    for (size_t i = 0; i < 4; ++i) largest[i] = std::max(largest[i], c[i]);
  }
  WindowChange total;
  total.edge = std::max(largest[0], largest[2]);
  // Per side: columns to add (or to spare) for the edge change to meet the tolerance.
  int grow = std::numeric_limits<int>::min();
  for (int side = 0; side < 2; ++side) {
    const int outer = probes[static_cast<size_t>(2 * side)], inner = probes[static_cast<size_t>(2 * side + 1)];
    if (outer < 0) continue;
    const double e0 = largest[static_cast<size_t>(2 * side)], e1 = largest[static_cast<size_t>(2 * side + 1)];
    int need;
    const int reach = side == 0 ? affectedLo - a : b - affectedHi;  // columns beyond the affected ones
    if (inner < 0 || !(e1 > e0) || !(e0 > 0.0)) {
      // No usable decay. Too large: double. Within tolerance (often exactly 0: far from other
      // removed knots the fine rows are unit rows and pin their columns): spare half, so the
      // window shrinks back instead of growing by the margin after every removal.
      need = e0 > tolerance_ ? reach : -reach / 2;
    } else {
      const double perColumn = std::log(e1 / e0) / std::abs(outer - inner);
      need = static_cast<int>(std::ceil(std::log(e0 / tolerance_) / perColumn));
    }
    grow = std::max(grow, need);
  }
  total.resize = grow == std::numeric_limits<int>::min() ? 0 : grow;
  ++stats_.windowSolves;
  stats_.widestWindow = std::max(stats_.widestWindow, w);
  return total;
}

bool ReductionPass::tryRemove(int knot, ErrorMeasure measure, double target, double* measured) {
  const int p = p_;
  const size_t k = static_cast<size_t>(columns_);
  const int pos = static_cast<int>(std::lower_bound(fineIndex_.begin(), fineIndex_.end(), knot) -
                                   fineIndex_.begin());
  const int n1 = controlCount() - 1;  // control points once the knot is gone
  xNew_ = x_;
  xNew_.erase(xNew_.begin() + pos);
  // New coarse functions pos − p − 1 … pos − 1 replace the old pos − p − 1 … pos; every other
  // function is unchanged, with index i below and i + 1 above (old numbering).
  const int affectedLo = pos - p - 1, affectedHi = pos - 1;
  const auto yEnd = y_.begin() + m_;

  int window = window_, a = 0, b = 0, ja = 0, jb = 0;
  WindowChange change;
  for (;;) {
    a = std::max(0, affectedLo - window);
    b = std::min(n1 - 1, affectedHi + window);
    // Fine rows touching columns [a, b]: span μ ≥ a ⟺ y_j ≥ x_a, and μ ≤ b + p ⟺ y_j < x_{b+p+1}.
    ja = static_cast<int>(std::lower_bound(y_.begin(), yEnd, xNew_[static_cast<size_t>(a)]) - y_.begin());
    jb = static_cast<int>(std::lower_bound(y_.begin(), yEnd, xNew_[static_cast<size_t>(b + p + 1)]) - y_.begin());
    change = solveWindow(pos, a, b, ja, jb);
    const bool whole = a == 0 && b == n1 - 1;
    if (change.edge <= tolerance_ || whole) break;
    window += std::max(change.resize, 0) + 2;
    ++stats_.windowRetries;
  }

  // The error of the fine slabs that changed; rows are independent, split among threads.
  const int rows = jb - ja;
  newSum_.resize(static_cast<size_t>(rows));
  newMax_.resize(static_cast<size_t>(rows));
  const int parts = static_cast<double>(rows) * static_cast<double>(error_.others) > 5e4 ? threads_ : 1;
  parallelParts(static_cast<unsigned>(parts), [&](int part) {
    const int r0 = rows * part / parts, r1 = rows * (part + 1) / parts;
    error_.measure(ja + r0, ja + r1, pRows_.data() + static_cast<size_t>(r0) * k, columns_,
                   newSum_.data() + r0, newMax_.data() + r0);
  });
  stats_.slabsMeasured += rows;
  double total = 0.0, largest = 0.0;
  for (int j = 0; j < m_; ++j) {
    const bool changed = j >= ja && j < jb;
    total += changed ? newSum_[static_cast<size_t>(j - ja)] : slabSum_[static_cast<size_t>(j)];
    largest = std::max(largest, changed ? newMax_[static_cast<size_t>(j - ja)] : slabMax_[static_cast<size_t>(j)]);
  }
  *measured = measure == ErrorMeasure::Mean ? total / pointCount_ : largest;
  if (*measured > target) return false;

  // Commit: the window's new rows go into the slots of the old window rows a … b + 1, the
  // last of which is dropped.
  for (int col = a; col <= b; ++col) {
    std::memcpy(qRow_[static_cast<size_t>(col)], z_.data() + static_cast<size_t>(col - a) * k,
                k * sizeof(double));
  }
  qRow_.erase(qRow_.begin() + b + 1);
  x_.swap(xNew_);
  fineIndex_.erase(fineIndex_.begin() + pos);
  std::copy(newSum_.begin(), newSum_.end(), slabSum_.begin() + ja);
  std::copy(newMax_.begin(), newMax_.end(), slabMax_.begin() + ja);
  total_ = total;
  // Start the next removal with the window this one needed plus a margin: knot spacing, and
  // so the decay, changes slowly along a curve.
  window_ = std::max(minWindow_, window + std::min(change.resize, 0) + 2);
  return true;
}

}  // namespace tessera
