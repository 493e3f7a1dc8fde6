#include "reduction/detail/order.h"

#include <algorithm>
#include <numeric>

namespace tessera {

KnotSchedule::KnotSchedule(const BSplineSurface& s, ParamDirection d,
                           const ReductionOptions& options)
    : choice_(options.choice) {
  const bool alongU = d == ParamDirection::U;
  const int p = alongU ? s.degreeU : s.degreeV;
  const int count = alongU ? s.countU : s.countV;
  count_ = std::max(0, count - p - 1);
  if (choice_ != KnotChoice::Curvature) order_ = removalOrder(s, d, options);
  if (choice_ != KnotChoice::Curvature && choice_ != KnotChoice::CurvatureSweeps) return;
  knots_ = alongU ? s.knotsU : s.knotsV;
  const int n = static_cast<int>(knots_.size());
  prev_.resize(static_cast<size_t>(n));
  next_.resize(static_cast<size_t>(n));
  std::iota(prev_.begin(), prev_.end(), -1);
  std::iota(next_.begin(), next_.end(), 1);
  removedInSweep_.assign(static_cast<size_t>(n), -1);
  if (choice_ == KnotChoice::CurvatureSweeps) return;
  bending_ = knotBending(s, d, options.aggregate);
  scoreOf_.assign(static_cast<size_t>(n), 0.0);
  for (int k = p + 1; k < count; ++k) {
    scoreOf_[static_cast<size_t>(k)] = score(k);
    queue_.emplace(scoreOf_[static_cast<size_t>(k)], k);
  }
}

double KnotSchedule::score(int k) const {
  const int a = prev_[static_cast<size_t>(k)], b = next_[static_cast<size_t>(k)];
  // Only k and knots already removed lie strictly between a and b (bending_ is 0 at the
  // clamped ends, which are never removed).
  double bending = 0.0;
  for (int j = a + 1; j < b; ++j) bending = std::max(bending, bending_[static_cast<size_t>(j)]);
  const double h = knots_[static_cast<size_t>(b)] - knots_[static_cast<size_t>(a)];
  return bending * h * h;
}

int KnotSchedule::nextInSweeps() {
  for (;;) {
    if (at_ == order_.size()) {
      if (deferred_.empty()) return -1;
      order_.swap(deferred_);
      deferred_.clear();
      at_ = 0;
      ++sweep_;
    }
    const int k = order_[at_++];
    bool crowded = false;
    for (int j = prev_[static_cast<size_t>(k)] + 1; j < next_[static_cast<size_t>(k)]; ++j) {
      crowded |= removedInSweep_[static_cast<size_t>(j)] == sweep_;
    }
    if (!crowded) return k;
    deferred_.push_back(k);
  }
}

int KnotSchedule::next() {
  switch (choice_) {
    case KnotChoice::Curvature: {
      if (queue_.empty()) return -1;
      const int k = queue_.begin()->second;
      queue_.erase(queue_.begin());
      return k;
    }
    case KnotChoice::CurvatureSweeps: return nextInSweeps();
    default: return at_ < order_.size() ? order_[at_++] : -1;
  }
}

void KnotSchedule::record(int k, bool removed) {
  if (!removed || prev_.empty()) return;
  const int a = prev_[static_cast<size_t>(k)], b = next_[static_cast<size_t>(k)];
  next_[static_cast<size_t>(a)] = b;
  prev_[static_cast<size_t>(b)] = a;
  removedInSweep_[static_cast<size_t>(k)] = sweep_;
  if (choice_ != KnotChoice::Curvature) return;
  // Only the two neighbours' spans changed; re-rank them if they are still to be tried.
  for (int j : {a, b}) {
    const auto entry = queue_.find({scoreOf_[static_cast<size_t>(j)], j});
    if (entry == queue_.end()) continue;
    queue_.erase(entry);
    scoreOf_[static_cast<size_t>(j)] = score(j);
    queue_.emplace(scoreOf_[static_cast<size_t>(j)], j);
  }
}

}  // namespace tessera
