#include "mesh/near_points.h"

#include <algorithm>

namespace tessera {

std::vector<std::pair<float, float>> nearPairs(std::vector<LinePoint>& points,
                                               const std::function<bool(float, float)>& distinct) {
  size_t count = points.size();
  std::vector<std::pair<float, float>> pairs = nearPairs(points.data(), count, distinct);
  points.resize(count);
  return pairs;
}

namespace {

// A line's points arrive as a few ascending runs (the leaves along it, each side's in turn),
// and most t twice (the leaves on either side): an insertion sort into the sorted, folded
// points so far moves each point past the few it is out of order with and folds a repeated t
// where it meets it, where std::sort partitions any line over 16 points and every point is
// folded after. The same points either way: equal t become one, whichever came first. Longer
// lines (none on the tea set at 10⁻³; 64 here cost it ~1.3 M instructions a call) keep
// std::sort's bound.
constexpr size_t kInsertionSortUpTo = 256;

// Sorts points[0, count) by t, folds equal t into one (the shortest spacing) and returns how
// many points are left.
size_t sortAndFold(LinePoint* points, size_t count) {
  // A long line is sorted first; the pass below then only folds (no point moves back).
  if (count > kInsertionSortUpTo)
    std::sort(points, points + count,
              [](const LinePoint& a, const LinePoint& b) { return a.t < b.t; });
  size_t kept = 0;
  // Where the last point went: a later run (the leaves on the line's other side) goes back
  // to the start of an earlier one and then climbs it, each point near the last one's place,
  // where searching back from the end crossed the rest of the earlier run every time.
  size_t last = 0;
  for (size_t k = 0; k < count; ++k) {
    const LinePoint point = points[k];
    size_t j = kept;
    if (j > 0 && point.t < points[j - 1].t) {
      // The first place whose point is past t (the points so far are distinct, ascending).
      j = std::min(last, kept);
      while (j < kept && points[j].t <= point.t) ++j;
      while (j > 0 && point.t < points[j - 1].t) --j;
    }
    last = j;
    if (j > 0 && points[j - 1].t == point.t) {
      points[j - 1].spacing = std::min(points[j - 1].spacing, point.spacing);
      continue;
    }
    for (size_t m = kept; m > j; --m) points[m] = points[m - 1];
    points[j] = point;
    ++kept;
    last = j + 1;
  }
  return kept;
}

}  // namespace

std::vector<std::pair<float, float>> nearPairs(LinePoint* points, size_t& count,
                                               const std::function<bool(float, float)>& distinct) {
  count = sortAndFold(points, count);
  std::vector<std::pair<float, float>> pairs;
  for (size_t k = 0; k + 1 < count; ++k) {
    const LinePoint& a = points[k];
    const LinePoint& b = points[k + 1];
    const float gap = b.t - a.t;
    const float spacing = std::min(a.spacing, b.spacing);
    if (gap <= kMergeFraction * spacing || (gap < spacing && !distinct(a.t, b.t)))
      pairs.emplace_back(a.t, b.t);
  }
  return pairs;
}

}  // namespace tessera
