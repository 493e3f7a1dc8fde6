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

std::vector<std::pair<float, float>> nearPairs(LinePoint* points, size_t& count,
                                               const std::function<bool(float, float)>& distinct) {
  std::sort(points, points + count,
            [](const LinePoint& a, const LinePoint& b) { return a.t < b.t; });
  size_t kept = 0;
  for (size_t k = 0; k < count; ++k) {
    if (kept > 0 && points[kept - 1].t == points[k].t)
      points[kept - 1].spacing = std::min(points[kept - 1].spacing, points[k].spacing);
    else
      points[kept++] = points[k];
  }
  count = kept;
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
