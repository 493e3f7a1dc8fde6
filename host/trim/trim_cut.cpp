#include "trim/trim_cut.h"

#include <algorithm>
#include <cmath>

namespace tessera {
namespace {

// The grid cell of coordinate x, clamped in double before the conversion (a far coordinate
// would overflow int).
int cellIndex(double x, double lo, double cell, int count) {
  return int(std::clamp(std::floor((x - lo) / cell), 0.0, double(count - 1)));
}

}  // namespace

TrimSegmentIndex::TrimSegmentIndex(const std::vector<TrimLoop>& loops) {
  size_t count = 0;
  for (const TrimLoop& loop : loops) count += loop.uv.size();
  segments_.reserve(count);
  for (const TrimLoop& loop : loops)
    for (size_t k = 0; k < loop.uv.size(); ++k)
      segments_.push_back({loop.uv[k], loop.uv[(k + 1) % loop.uv.size()]});
  if (segments_.empty()) return;
  lo_ = hi_ = segments_[0].a;
  for (const TrimSegment& s : segments_) {
    lo_ = glm::min(lo_, glm::min(s.a, s.b));
    hi_ = glm::max(hi_, glm::max(s.a, s.b));
  }
  // About one segment a cell on average (√n × √n cells), at most 256 a side.
  const int side = std::clamp(int(std::sqrt(double(segments_.size()))), 1, 256);
  cellsU_ = cellsV_ = side;
  cell_ = glm::max((hi_ - lo_) / double(side), glm::dvec2(1e-300));
  // The bins as one array (counts, then offsets, then each segment's ids in increasing order,
  // as per-cell vectors held them) instead of a vector per cell.
  stamp_.assign(segments_.size(), 0);
  std::vector<std::array<int, 4>> spans(segments_.size());  // u0, u1, v0, v1
  binStart_.assign(size_t(cellsU_) * cellsV_ + 1, 0);
  for (uint32_t s = 0; s < segments_.size(); ++s) {
    const glm::dvec2 a = glm::min(segments_[s].a, segments_[s].b);
    const glm::dvec2 b = glm::max(segments_[s].a, segments_[s].b);
    std::array<int, 4>& span = spans[s];
    span = {cellIndex(a.x, lo_.x, cell_.x, cellsU_), cellIndex(b.x, lo_.x, cell_.x, cellsU_),
            cellIndex(a.y, lo_.y, cell_.y, cellsV_), cellIndex(b.y, lo_.y, cell_.y, cellsV_)};
    for (int i = span[0]; i <= span[1]; ++i)
      for (int j = span[2]; j <= span[3]; ++j) ++binStart_[size_t(i) * cellsV_ + j + 1];
  }
  for (size_t c = 1; c < binStart_.size(); ++c) binStart_[c] += binStart_[c - 1];
  binned_.resize(binStart_.back());
  std::vector<uint32_t> fill(binStart_.begin(), binStart_.end() - 1);
  for (uint32_t s = 0; s < segments_.size(); ++s) {
    const std::array<int, 4>& span = spans[s];
    for (int i = span[0]; i <= span[1]; ++i)
      for (int j = span[2]; j <= span[3]; ++j) binned_[fill[size_t(i) * cellsV_ + j]++] = s;
  }
}

void TrimSegmentIndex::near(glm::dvec2 lo, glm::dvec2 hi, std::vector<uint32_t>& out) const {
  out.clear();
  if (segments_.empty() || hi.x < lo_.x || hi.y < lo_.y || lo.x > hi_.x || lo.y > hi_.y) return;
  if (++query_ == 0) std::fill(stamp_.begin(), stamp_.end(), 0), query_ = 1;
  const int u0 = cellIndex(lo.x, lo_.x, cell_.x, cellsU_);
  const int u1 = cellIndex(hi.x, lo_.x, cell_.x, cellsU_);
  const int v0 = cellIndex(lo.y, lo_.y, cell_.y, cellsV_);
  const int v1 = cellIndex(hi.y, lo_.y, cell_.y, cellsV_);
  for (int i = u0; i <= u1; ++i)
    for (int j = v0; j <= v1; ++j)
      for (uint32_t s : bin(size_t(i) * cellsV_ + j))
        if (stamp_[s] != query_) {
          stamp_[s] = query_;
          out.push_back(s);
        }
}

namespace {

// Sunday's crossing rule: an upward edge with p strictly left of it adds 1, a downward edge
// with p strictly right subtracts 1 (half-open in v, so a vertex at p's height counts once).
// Non-zero only when p's v lies in the segment's v-range and the line passes right of p: for
// p.x ≥ both ends' x, the rounded side's sign is never the counting one (rounding is monotone).
int crossing(const TrimSegment& s, glm::dvec2 p) {
  const double side = (s.b.x - s.a.x) * (p.y - s.a.y) - (p.x - s.a.x) * (s.b.y - s.a.y);
  if (s.a.y <= p.y) return s.b.y > p.y && side > 0 ? 1 : 0;
  return s.b.y <= p.y && side < 0 ? -1 : 0;
}

}  // namespace

int trimWindingNumber(const std::vector<TrimSegment>& segments, glm::dvec2 p) {
  int winding = 0;
  for (const TrimSegment& s : segments) winding += crossing(s, p);
  return winding;
}

int TrimSegmentIndex::windingNumber(glm::dvec2 p) const {
  if (segments_.empty()) return 0;
  if (++query_ == 0) std::fill(stamp_.begin(), stamp_.end(), 0), query_ = 1;
  const int j = cellIndex(p.y, lo_.y, cell_.y, cellsV_);
  int winding = 0;
  for (int i = cellIndex(p.x, lo_.x, cell_.x, cellsU_); i < cellsU_; ++i)
    for (uint32_t s : bin(size_t(i) * cellsV_ + j))
      if (stamp_[s] != query_) {
        stamp_[s] = query_;
        winding += crossing(segments_[s], p);
      }
  return winding;
}

namespace {

double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

double pointSegmentDistance(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 d = b - a;
  const double length2 = glm::dot(d, d);
  const double t = length2 > 0 ? std::clamp(glm::dot(p - a, d) / length2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * d));
}

bool insideTriangle(glm::dvec2 p, const std::array<glm::dvec2, 3>& t) {
  const double d0 = cross(t[1] - t[0], p - t[0]), d1 = cross(t[2] - t[1], p - t[1]),
               d2 = cross(t[0] - t[2], p - t[2]);
  return (d0 >= 0 && d1 >= 0 && d2 >= 0) || (d0 <= 0 && d1 <= 0 && d2 <= 0);
}

}  // namespace

namespace {

bool properCrossing(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 q0, glm::dvec2 q1) {
  const double a = cross(p1 - p0, q0 - p0), b = cross(p1 - p0, q1 - p0);
  const double c = cross(q1 - q0, p0 - q0), d = cross(q1 - q0, p1 - q0);
  return ((a > 0 && b < 0) || (a < 0 && b > 0)) && ((c > 0 && d < 0) || (c < 0 && d > 0));
}

double endDistance(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 q0, glm::dvec2 q1) {
  return std::min({pointSegmentDistance(p0, q0, q1), pointSegmentDistance(p1, q0, q1),
                   pointSegmentDistance(q0, p0, p1), pointSegmentDistance(q1, p0, p1)});
}

}  // namespace

double segmentDistance(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 q0, glm::dvec2 q1) {
  if (properCrossing(p0, p1, q0, q1)) return 0;
  return endDistance(p0, p1, q0, q1);
}

bool segmentsFartherThan(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 q0, glm::dvec2 q1,
                         double distance) {
  // The crossing test first: on four points nearly on one line its signs are rounding, and
  // segmentDistance says 0 when they say crossing, however far apart the boxes.
  if (properCrossing(p0, p1, q0, q1)) return 0 > distance;
  // Boxes apart by g: every end's distance to the other segment is at least g, and its computed
  // value at least g less a few ulps of the coordinates' magnitude m (10⁻¹² m is far more).
  const glm::dvec2 pLo = glm::min(p0, p1), pHi = glm::max(p0, p1);
  const glm::dvec2 qLo = glm::min(q0, q1), qHi = glm::max(q0, q1);
  const glm::dvec2 apart = glm::max(qLo - pHi, pLo - qHi);
  const glm::dvec2 m = glm::max(glm::max(glm::abs(p0), glm::abs(p1)), glm::max(glm::abs(q0), glm::abs(q1)));
  if (std::max(apart.x, apart.y) > distance + 1e-12 * std::max(m.x, m.y)) return true;
  return endDistance(p0, p1, q0, q1) > distance;
}

namespace {

// Whether segmentsFartherThan(s.a, s.b, q0, q1, margin) holds for every side (q0, q1) of a
// triangle whose corners lie in the box [lo, hi], their largest |coordinate| `reach`, from the
// box alone (one test where the three sides took three). Its crossing test needs the signs of
// cross(s.b − s.a, q − s.a) at q0 and q1 to differ; that rounded product is monotone in q.x and
// in q.y, so where it is > 0 at the box's corner where it is least (or < 0 where it is largest)
// no two corners differ. Its box test passes for each side when it passes for the whole box:
// a side's gap to the segment is at least the box's, its allowance for rounding at most the
// box's (rounding is monotone). False says nothing: the sides are then tested one by one.
bool farFromBox(const TrimSegment& s, glm::dvec2 lo, glm::dvec2 hi, glm::dvec2 reach,
                double margin) {
  const glm::dvec2 e = s.b - s.a;
  const glm::dvec2 least(e.y >= 0 ? hi.x : lo.x, e.x >= 0 ? lo.y : hi.y);
  const glm::dvec2 largest(e.y >= 0 ? lo.x : hi.x, e.x >= 0 ? hi.y : lo.y);
  if (!(cross(e, least - s.a) > 0 || cross(e, largest - s.a) < 0)) return false;
  const glm::dvec2 sLo = glm::min(s.a, s.b), sHi = glm::max(s.a, s.b);
  const glm::dvec2 apart = glm::max(lo - sHi, sLo - hi);
  const glm::dvec2 m = glm::max(glm::max(glm::abs(s.a), glm::abs(s.b)), reach);
  return std::max(apart.x, apart.y) > margin + 1e-12 * std::max(m.x, m.y);
}

}  // namespace

TrimClass classifyTrimTriangle(const std::array<glm::dvec2, 3>& triangle,
                               const TrimSegmentIndex& index, double margin) {
  const glm::dvec2 boxLo = glm::min(triangle[0], glm::min(triangle[1], triangle[2]));
  const glm::dvec2 boxHi = glm::max(triangle[0], glm::max(triangle[1], triangle[2]));
  const glm::dvec2 reach =
      glm::max(glm::abs(triangle[0]), glm::max(glm::abs(triangle[1]), glm::abs(triangle[2])));
  const glm::dvec2 lo = boxLo - margin, hi = boxHi + margin;
  thread_local std::vector<uint32_t> nearby;
  index.near(lo, hi, nearby);
  for (uint32_t s : nearby) {
    const TrimSegment& seg = index.segments()[s];
    if (insideTriangle(seg.a, triangle)) return TrimClass::Crossing;
    if (farFromBox(seg, boxLo, boxHi, reach, margin)) continue;
    // segmentDistance(…) ≤ margin, decided without its four point-segment distances when the
    // boxes lie apart (most of the segments the grid's cells bring are not near this side).
    for (int k = 0; k < 3; ++k)
      if (!segmentsFartherThan(seg.a, seg.b, triangle[k], triangle[(k + 1) % 3], margin))
        return TrimClass::Crossing;
  }
  const glm::dvec2 centroid = (triangle[0] + triangle[1] + triangle[2]) / 3.0;
  return index.windingNumber(centroid) > 0 ? TrimClass::Inside : TrimClass::Outside;
}

}  // namespace tessera
