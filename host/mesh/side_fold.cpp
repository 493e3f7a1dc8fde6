#include "mesh/side_fold.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace tessera {
namespace {

// de Casteljau on a copy of c: on the stack for a side's few points (the fold search calls it
// 256 times a side), the same arithmetic either way.
double bernstein(const std::vector<double>& c, double t) {
  std::array<double, 16> small;
  std::vector<double> large;
  double* b = small.data();
  if (c.size() > small.size()) b = (large = c).data();
  else std::copy(c.begin(), c.end(), small.begin());
  for (size_t r = 1; r < c.size(); ++r)
    for (size_t k = 0; k + r < c.size(); ++k) b[k] = (1 - t) * b[k] + t * b[k + 1];
  return b[0];
}

// The parameter in [lo, hi] where the monotone s reaches `target` (bisection).
double solveOnStrand(const SideFold& fold, double lo, double hi, double target) {
  const bool rising = foldCoordinate(fold, hi) > foldCoordinate(fold, lo);
  for (int k = 0; k < 200 && lo < hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    if ((foldCoordinate(fold, mid) < target) == rising)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

std::optional<SideFold> findSideFold(const std::vector<glm::dvec3>& points) {
  if (points.size() < 3) return std::nullopt;
  // The line: from the first point towards the point farthest from it.
  glm::dvec3 direction(0);
  for (const glm::dvec3& p : points)
    if (glm::length(p - points[0]) > glm::length(direction)) direction = p - points[0];
  const double extent = glm::length(direction);
  if (extent == 0) return std::nullopt;  // a collapsed side
  direction /= extent;
  SideFold fold;
  for (const glm::dvec3& p : points) {
    const glm::dvec3 d = p - points[0];
    if (glm::length(d - glm::dot(d, direction) * direction) > 1e-12 * extent) return std::nullopt;
    fold.coordinate.push_back(glm::dot(d, direction));
  }
  // Turns: sign changes of s' (its Bernstein coefficients are the differences), located on a
  // fine grid and refined by bisection. A monotone control polygon cannot turn.
  std::vector<double> slope;
  for (size_t k = 0; k + 1 < fold.coordinate.size(); ++k)
    slope.push_back(fold.coordinate[k + 1] - fold.coordinate[k]);
  if (std::all_of(slope.begin(), slope.end(), [](double d) { return d >= 0; }) ||
      std::all_of(slope.begin(), slope.end(), [](double d) { return d <= 0; }))
    return std::nullopt;
  fold.strands.push_back(0.0);
  const int samples = 256;
  double previousT = 0, previous = bernstein(slope, 0);
  for (int i = 1; i <= samples; ++i) {
    const double t = double(i) / samples, d = bernstein(slope, t);
    if ((previous < 0 && d > 0) || (previous > 0 && d < 0)) {
      double lo = previousT, hi = t;
      for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (lo + hi);
        if (mid == lo || mid == hi) break;
        ((bernstein(slope, mid) < 0) == (previous < 0) ? lo : hi) = mid;
      }
      fold.strands.push_back(0.5 * (lo + hi));
    }
    if (d != 0) previous = d, previousT = t;
  }
  if (fold.strands.size() == 1) return std::nullopt;  // touches zero slope but never turns
  fold.strands.push_back(1.0);
  return fold;
}

double foldCoordinate(const SideFold& fold, double t) {
  if (t == 0) return fold.coordinate.front();
  if (t == 1) return fold.coordinate.back();
  return bernstein(fold.coordinate, t);
}

std::vector<double> foldImages(const SideFold& fold, double t, double s) {
  std::vector<double> images;
  for (size_t j = 0; j + 1 < fold.strands.size(); ++j) {
    const double lo = fold.strands[j], hi = fold.strands[j + 1];
    if (t >= lo && t <= hi) continue;  // t's own strand
    const double a = foldCoordinate(fold, lo), b = foldCoordinate(fold, hi);
    if (s < std::min(a, b) || s > std::max(a, b)) continue;
    images.push_back(s == a ? lo : s == b ? hi : solveOnStrand(fold, lo, hi, s));
  }
  return images;
}

}  // namespace tessera
