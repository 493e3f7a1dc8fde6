#include "trim/detail/gap_refine.h"

#include "common/hash_map.h"
#include "common/small_id_list.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace tessera::trim_detail {
namespace {

double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

// 2·area / (longest side)² = the height over the longest side / that side (negative: clockwise).
double shapeRatio(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
  const double longest2 =
      std::max({glm::dot(b - a, b - a), glm::dot(c - b, c - b), glm::dot(a - c, a - c)});
  return longest2 > 0 ? cross(b - a, c - a) / longest2 : 0.0;
}

// A sliver's longest side goes to the triangle across it by a flip when its height is under 1%
// of that side: the flip removes it, a midpoint split would keep both halves as thin.
constexpr double kFlipSliverRatio = 0.01;
// A sliver flip is taken only when it at least doubles the thinner triangle's height ratio.
// Any gain at all let rounds pass in flips among points nearly on one uv line, each a little
// less thin, with no split: a rational cone's wide gap stayed 2δ off when the rounds ran out
// (test "gap refinement: a rational cone's wide gaps end within δ").
constexpr double kFlipSliverGain = 2.0;

// The edge → triangles map kept in step with every split and flip, hashed by the edge's exact
// 64-bit key (smaller vertex in the high word).
class EdgeUsers {
 public:
  explicit EdgeUsers(const std::vector<FaceTriangle>& triangles) {
    users_.reserve(2 * triangles.size());  // about 3/2 edges a triangle
    for (uint32_t t = 0; t < triangles.size(); ++t) add(triangles[t].v, t);
  }
  void add(const std::array<uint32_t, 3>& v, uint32_t t) {
    for (int k = 0; k < 3; ++k) users_[key(v[k], v[(k + 1) % 3])].push_back(t);
  }
  void add(uint32_t a, uint32_t b, uint32_t t) { users_[key(a, b)].push_back(t); }
  void replace(uint32_t a, uint32_t b, uint32_t from, uint32_t to) {
    users_[key(a, b)].replace(from, to);
  }
  void erase(uint32_t a, uint32_t b) { users_.erase(key(a, b)); }
  // The edges with exactly two triangles that `keep` accepts, in increasing (smaller, larger)
  // order: the order does not depend on the hashing.
  template <class Keep>
  std::vector<EdgeKey> sharedEdges(Keep&& keep) const {
    std::vector<uint64_t> keys;
    for (const auto& [k, ts] : users_)
      if (ts.size() == 2 && keep(ts)) keys.push_back(k);
    std::sort(keys.begin(), keys.end());
    std::vector<EdgeKey> edges;
    edges.reserve(keys.size());
    for (uint64_t k : keys) edges.push_back({uint32_t(k >> 32), uint32_t(k)});
    return edges;
  }
  SmallIdList of(uint32_t a, uint32_t b) const {
    const auto found = users_.find(key(a, b));
    return found == users_.end() ? SmallIdList() : found->second;
  }

 private:
  static uint64_t key(uint32_t a, uint32_t b) {
    return uint64_t(std::min(a, b)) << 32 | uint64_t(std::max(a, b));
  }
  HashMap<uint64_t, SmallIdList> users_;
};

// The position of the triangle's side k (its corners k, k + 1) and the rotation that puts it first.
std::array<uint32_t, 3> rotated(const std::array<uint32_t, 3>& v, int k) {
  return {v[k], v[(k + 1) % 3], v[(k + 2) % 3]};
}

int sideOf(const std::array<uint32_t, 3>& v, uint32_t a, uint32_t b) {
  for (int k = 0; k < 3; ++k)
    if (edgeKey(v[k], v[(k + 1) % 3]) == edgeKey(a, b)) return k;
  return -1;
}

// A triangle's measures (negative: not taken yet), by its corners in any order.
struct Measures {
  SampledDeviations sampled{-1.0, -1.0};  // interpolation and parametric (with the corners' offsets)
  double geometric = -1.0;  // 0 within δ (interpolationWithinFrom), +∞ over it
  // The corners in the order of the first triangle that asked for `sampled`: an inner sample's
  // uv sums the corners in this order (the last bit may differ in another), so `sampled` is
  // always taken in it, when it is taken, as it was when it was taken at the first asking.
  std::array<uint32_t, 3> order{};
  bool ordered = false;
};
class MeasureCache {
 public:
  explicit MeasureCache(size_t expected) { byCorners_.reserve(expected); }
  // The reference lives until the next call of of() (the flat map moves its entries).
  Measures& of(std::array<uint32_t, 3> v) {
    std::sort(v.begin(), v.end());
    return byCorners_[v];
  }
  const Measures* find(std::array<uint32_t, 3> v) const {
    std::sort(v.begin(), v.end());
    const auto it = byCorners_.find(v);
    return it == byCorners_.end() ? nullptr : &it->second;
  }

 private:
  struct Hash {
    size_t operator()(const std::array<uint32_t, 3>& v) const {
      return size_t((uint64_t(v[0]) * 0x9E3779B97F4A7C15ull) ^ (uint64_t(v[1]) << 32 | v[2]));
    }
  };
  HashMap<std::array<uint32_t, 3>, Measures, Hash> byCorners_;
};

// S(uv) of each vertex, evaluated once: the measures and the split choice ask for a corner's
// surface point every time they see the triangle. A vertex the refinement adds is on the
// surface (its position is S(uv), the same call).
class CornerPoints {
 public:
  CornerPoints(const FaceSurface& surface, const std::vector<FaceVertex>& vs)
      : surface_(surface), vs_(vs) {}
  glm::dvec3 operator()(uint32_t v) {  // a copy: the next call may grow the array
    grow();
    if (!known_[v]) points_[v] = surface_.point(vs_[v].uv), known_[v] = 1;
    return points_[v];
  }
  void addOnSurface(uint32_t v) {
    grow();
    points_[v] = vs_[v].position, known_[v] = 1;
  }
  std::array<glm::dvec3, 3> of(const std::array<uint32_t, 3>& t) {
    return {(*this)(t[0]), (*this)(t[1]), (*this)(t[2])};
  }

 private:
  const FaceSurface& surface_;
  const std::vector<FaceVertex>& vs_;
  std::vector<glm::dvec3> points_;
  std::vector<char> known_;
  void grow() {
    if (known_.size() < vs_.size()) points_.resize(vs_.size()), known_.resize(vs_.size(), 0);
  }
};

// When each triangle last changed and when each edge was last found not worth a deviation flip,
// on one clock. The finding reads only the edge's two triangles and measures fixed by their
// corners, so while neither triangle changes it stands, and the edge is not judged again (each
// flip pass judged every shared edge, most of them unchanged since the pass before). Only
// findings on an edge with exactly two triangles are kept: those two are then its triangles
// for as long as neither changes. The edges of the triangles changed since the last pass began
// are kept too: with the edges found before, they are the only ones a pass can judge anew.
class FlipFindings {
 public:
  static uint64_t key(const EdgeKey& e) { return uint64_t(e.first) << 32 | e.second; }
  static EdgeKey edgeOf(uint64_t k) { return {uint32_t(k >> 32), uint32_t(k)}; }

  void changed(uint32_t t, const std::array<uint32_t, 3>& v) {
    if (t >= changedAt_.size()) changedAt_.resize(size_t(t) + 1, 0);
    changedAt_[t] = ++clock_;
    for (int k = 0; k < 3; ++k) pending_.push_back(key(edgeKey(v[k], v[(k + 1) % 3])));
  }
  void noFlip(const EdgeKey& edge) { noFlipAt_[key(edge)] = clock_; }
  bool stillNoFlip(const EdgeKey& edge, uint32_t t, uint32_t s) const {
    const auto found = noFlipAt_.find(key(edge));
    return found != noFlipAt_.end() && lastChange(t) <= found->second &&
           lastChange(s) <= found->second;
  }
  // The edges of the triangles changed since the last call, sorted and distinct; the first call
  // answers everyEdge() (none has been judged).
  template <class EveryEdge>
  std::vector<uint64_t> takePending(EveryEdge&& everyEdge) {
    std::vector<uint64_t> edges;
    if (first_) {
      first_ = false, pending_.clear();
      for (const EdgeKey& e : everyEdge()) edges.push_back(key(e));
      return edges;
    }
    edges.swap(pending_);
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return edges;
  }

 private:
  uint64_t lastChange(uint32_t t) const { return t < changedAt_.size() ? changedAt_[t] : 0; }
  uint64_t clock_ = 0;
  std::vector<uint64_t> changedAt_;  // 0: not changed since the refinement began
  HashMap<uint64_t, uint64_t> noFlipAt_;
  std::vector<uint64_t> pending_;
  bool first_ = true;
};

}  // namespace

namespace {

// The largest `measure(point on the triangle, its uv)` over the samples (i, j, k)/n.
template <typename Measure>
double largestOverSamples(const std::vector<FaceVertex>& vs, const std::array<uint32_t, 3>& t,
                          int n, Measure measure) {
  double worst = 0;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const double a = double(i) / n, b = double(j) / n, c = 1 - a - b;
      const glm::dvec2 uv = a * vs[t[0]].uv + b * vs[t[1]].uv + c * vs[t[2]].uv;
      const glm::dvec3 p = a * vs[t[0]].position + b * vs[t[1]].position + c * vs[t[2]].position;
      worst = std::max(worst, measure(p, uv));
    }
  return worst;
}

}  // namespace

namespace {

// The largest squared interpolation and parametric terms over the n − 1 samples inside one
// side of a triangle. With n a power of two every weight i/n and 1 − a − b is exact, so such a
// sample's weights are (w, 1 − w) on the side's two corners and exactly 0 on the third: its uv,
// point, target and surface point are the same doubles in both triangles on the side (x·A +
// y·B = y·B + x·A, and adding 0·C changes at most a zero's sign, never a square), so the side's
// largest terms, a function of its two corners alone (vertices never move), are computed once
// for the two triangles.
struct SideSampleMax {
  double interpolation2 = 0, parametric2 = 0;
};
class SideSampleCache {
 public:
  explicit SideSampleCache(size_t expected) { bySide_.reserve(expected); }
  const SideSampleMax* find(uint32_t a, uint32_t b) const {
    const auto it = bySide_.find(key(a, b));
    return it == bySide_.end() ? nullptr : &it->second;
  }
  void store(uint32_t a, uint32_t b, const SideSampleMax& m) { bySide_[key(a, b)] = m; }

 private:
  static uint64_t key(uint32_t a, uint32_t b) {
    return uint64_t(std::min(a, b)) << 32 | uint64_t(std::max(a, b));
  }
  HashMap<uint64_t, SideSampleMax> bySide_;
};

// Whether a triangle's side samples may be shared (SideSampleCache): n a power of two, and every
// corner's uv, point and surface point finite (0·C is then ±0).
bool sidesShareable(const std::vector<FaceVertex>& vs, const std::array<uint32_t, 3>& t,
                    const std::array<glm::dvec3, 3>& s, int n) {
  if (n < 1 || (n & (n - 1)) != 0) return false;
  for (int k = 0; k < 3; ++k) {
    const FaceVertex& v = vs[t[k]];
    if (!(std::isfinite(v.uv.x) && std::isfinite(v.uv.y) && std::isfinite(v.position.x) &&
          std::isfinite(v.position.y) && std::isfinite(v.position.z) && std::isfinite(s[k].x) &&
          std::isfinite(s[k].y) && std::isfinite(s[k].z)))
      return false;
  }
  return true;
}

// A sample's barycentric weights as the (i, j) walks form them: a = i/n, b = j/n, c = 1 − a − b.
struct Weights {
  double a, b, c;
};

// The samples (i, j)/n of a triangle's sampling as weights, made once per thread for n (each
// walk divided twice a sample for them): `walk` holds all but the corners in the walk's order
// (i, then j), for interpolationWithinFrom; `parts` the same by part (0 inside, 1-3 a side, each
// in the walk's order), for sampledDeviationsFrom, which skips the sides it knows.
struct SamplePlan {
  int n = -1;
  std::vector<Weights> walk;
  std::array<std::vector<Weights>, 4> parts;
  std::array<Weights, 3> corners;  // i = n (t0), j = n (t1), i + j = 0 (t2)
};

const SamplePlan& samplePlan(int n) {
  thread_local SamplePlan plan;
  if (plan.n != n) {
    plan.walk.clear();
    for (std::vector<Weights>& weights : plan.parts) weights.clear();
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const double a = double(i) / n, b = double(j) / n, c = 1 - a - b;
        if (i == n || j == n || i + j == 0) {
          plan.corners[size_t(i == n ? 0 : j == n ? 1 : 2)] = {a, b, c};
          continue;
        }
        plan.walk.push_back({a, b, c});
        plan.parts[size_t(i + j == n ? 1 : i == 0 ? 2 : j == 0 ? 3 : 0)].push_back({a, b, c});
      }
    plan.n = n;
  }
  return plan;
}

// sampledDeviations with the corners' surface points s = S(uvᵢ) given. `sides`, when given,
// holds the side samples' largest terms of triangles measured before (SideSampleCache): a side
// found there is not sampled again, one not found is stored.
SampledDeviations sampledDeviationsFrom(const FaceSurface& surface,
                                        const std::vector<FaceVertex>& vs,
                                        const std::array<uint32_t, 3>& t,
                                        const std::array<glm::dvec3, 3>& s, int n,
                                        SideSampleCache* sides = nullptr) {
  const glm::dvec3 &s0 = s[0], &s1 = s[1], &s2 = s[2];
  const glm::dvec3 &p0 = vs[t[0]].position, &p1 = vs[t[1]].position, &p2 = vs[t[2]].position;
  // The largest squared lengths, one square root each at the end: √ is correctly rounded and
  // monotonic, so √(max d²) is max √(d²), glm::length's value, bit for bit (two roots a sample
  // were a fifth of the refinement's time). A max is the same whatever order its terms come in
  // (std::max drops a NaN term either way), so a side's terms may come from the cache.
  const auto squared = [](const glm::dvec3& d) { return glm::dot(d, d); };
  // [0]: the inner samples; [1 + k]: side k, 0 = (t0, t1) where i + j = n, 1 = (t1, t2) where
  // i = 0, 2 = (t2, t0) where j = 0.
  std::array<SideSampleMax, 4> part{};
  std::array<bool, 4> known{false, false, false, false};
  const bool share = sides && sidesShareable(vs, t, s, n);
  if (share)
    for (int k = 0; k < 3; ++k)
      if (const SideSampleMax* m = sides->find(t[k], t[(k + 1) % 3]))
        part[size_t(1 + k)] = *m, known[size_t(1 + k)] = true;
  // The samples' weights by part (samplePlan: the (i, j) walk with its part tests was a third
  // of this function's own time); a part's samples keep the walk's order.
  const SamplePlan& plan = samplePlan(n);
  // The buffers sized once per thread and written through plain pointers: a push_back stored
  // the thread-local vector's end after every sample (an eighth of this function's time).
  thread_local std::vector<glm::dvec2> uvBuffer;
  thread_local std::vector<glm::dvec3> onSurfaceBuffer;
  const size_t interior = size_t(n + 1) * size_t(n + 2) / 2;  // ≥ the samples but the corners
  if (uvBuffer.size() < interior) uvBuffer.resize(interior), onSurfaceBuffer.resize(interior);
  glm::dvec2* const uvs = uvBuffer.data();
  const glm::dvec3* const onSurface = onSurfaceBuffer.data();
  const glm::dvec2 uv0 = vs[t[0]].uv, uv1 = vs[t[1]].uv, uv2 = vs[t[2]].uv;
  // The surface points of the samples still to take (not a corner, not on a known side) in one
  // call (FaceSurface::points), then the measures.
  size_t count = 0;
  for (size_t k = 0; k < 4; ++k)
    if (!known[k])
      for (const Weights& w : plan.parts[k]) uvs[count++] = w.a * uv0 + w.b * uv1 + w.c * uv2;
  surface.points(uvs, count, onSurfaceBuffer.data());
  SampledDeviations worst2;  // squared
  for (size_t k = 0; k < 3; ++k) {  // a corner: its own offset, no interpolation error
    const Weights& w = plan.corners[k];
    const glm::dvec3 p = w.a * p0 + w.b * p1 + w.c * p2;
    worst2.parametric = std::max(worst2.parametric, squared(p - s[k]));
  }
  size_t next = 0;
  for (size_t k = 0; k < 4; ++k) {
    if (known[k]) continue;
    SideSampleMax& into = part[k];
    for (const Weights& w : plan.parts[k]) {
      const glm::dvec3 p = w.a * p0 + w.b * p1 + w.c * p2;
      const glm::dvec3& on = onSurface[next++];
      into.parametric2 = std::max(into.parametric2, squared(p - on));
      into.interpolation2 =
          std::max(into.interpolation2, squared(w.a * s0 + w.b * s1 + w.c * s2 - on));
    }
  }
  for (size_t k = 0; k < part.size(); ++k) {
    worst2.parametric = std::max(worst2.parametric, part[k].parametric2);
    worst2.interpolation = std::max(worst2.interpolation, part[k].interpolation2);
    if (share && k > 0 && !known[k]) sides->store(t[k - 1], t[k % 3], part[k]);
  }
  return {std::sqrt(worst2.interpolation), std::sqrt(worst2.parametric)};
}

// A lower bound of sampledDeviationsFrom(…, &sides).interpolation from the side terms already in
// `sides` alone, without sampling: that measure is the square root of the largest term over the
// inner samples and the three sides, a side's terms found in `sides` are the ones it would use,
// and √ of a largest term over fewer parts is no larger (0 when no side is known or the sides
// may not be shared).
double interpolationFromKnownSides(const std::vector<FaceVertex>& vs,
                                   const std::array<uint32_t, 3>& t,
                                   const std::array<glm::dvec3, 3>& s, int n,
                                   const SideSampleCache& sides) {
  if (!sidesShareable(vs, t, s, n)) return 0.0;
  double worst2 = 0;
  for (int k = 0; k < 3; ++k)
    if (const SideSampleMax* m = sides.find(t[k], t[(k + 1) % 3]))
      worst2 = std::max(worst2, m->interpolation2);
  return std::sqrt(worst2);
}

// Whether sampledDeviationsFrom(…).interpolation ≥ limit is certain from a few inner samples
// near the triangle's centre (where a bent surface leaves its chords most): each one's term is
// the one sampledDeviationsFrom takes there (the same uv, surface point and target, as doubles:
// FaceSurface::points gives point()'s), and that measure is the square root of the largest
// term, so one term at or over limit² decides. False says nothing.
bool interpolationProbeReaches(const FaceSurface& surface, const std::vector<FaceVertex>& vs,
                               const std::array<uint32_t, 3>& t,
                               const std::array<glm::dvec3, 3>& s, int n, double limit) {
  // The inner samples (i, j) nearest the centre, nearest first, for this n.
  thread_local std::vector<std::pair<int, int>> probes;
  thread_local int probesOf = -1;
  constexpr size_t kProbes = 3;
  if (probesOf != n) {
    std::vector<std::pair<double, std::pair<int, int>>> inner;
    for (int i = 1; i < n; ++i)
      for (int j = 1; i + j < n; ++j) {
        const double di = i - n / 3.0, dj = j - n / 3.0, dk = (n - i - j) - n / 3.0;
        inner.push_back({di * di + dj * dj + dk * dk, {i, j}});
      }
    std::stable_sort(inner.begin(), inner.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    probes.clear();
    for (size_t k = 0; k < inner.size() && k < kProbes; ++k) probes.push_back(inner[k].second);
    probesOf = n;
  }
  const glm::dvec2 uv0 = vs[t[0]].uv, uv1 = vs[t[1]].uv, uv2 = vs[t[2]].uv;
  for (const auto& [i, j] : probes) {
    const double a = double(i) / n, b = double(j) / n, c = 1 - a - b;
    const glm::dvec2 uv = a * uv0 + b * uv1 + c * uv2;
    const glm::dvec3 d = a * s[0] + b * s[1] + c * s[2] - surface.point(uv);
    if (std::sqrt(glm::dot(d, d)) >= limit) return true;
  }
  return false;
}

// interpolationDistance with the corners' surface points given, for the refinement, which asks
// only whether the triangle is within `limit`: a sample's search ends once within `limit`
// (FaceSurface::distance's `enough`), and the samples end at the first one over it (its
// distance is returned: the samples after it cannot bring the largest back under). The answer
// to "≤ limit" is the full measure's; the value is not. limit = +∞: the full measure.
double interpolationDistanceFrom(const FaceSurface& surface, const std::vector<FaceVertex>& vs,
                                 const std::array<uint32_t, 3>& t,
                                 const std::array<glm::dvec3, 3>& s, int n, double limit) {
  const glm::dvec3 &s0 = s[0], &s1 = s[1], &s2 = s[2];
  const double enough = limit < std::numeric_limits<double>::infinity() ? limit : 0.0;
  double worst = 0;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const double a = double(i) / n, b = double(j) / n, c = 1 - a - b;
      if (i == n || j == n || i + j == 0) continue;
      const glm::dvec2 uv = a * vs[t[0]].uv + b * vs[t[1]].uv + c * vs[t[2]].uv;
      worst = std::max(worst, surface.distance(a * s0 + b * s1 + c * s2, uv, enough));
      if (worst > limit) return worst;
    }
  return worst;
}

// Whether interpolationDistanceFrom(…, limit) ≤ limit, with fewer searches: a sample whose
// surface point S(uv) lies within limit − slack of its target Σ bᵢ S(uvᵢ) needs none, since
// the search starts at that uv and only ever lowers the distance, and its first evaluation of
// S(uv) (the partials' code, not point()'s) differs from point()'s by rounding, a few ulps of
// the net's coordinates, which `slack` covers many times over. The other samples are searched
// as interpolationDistanceFrom searches them (same target, guess and `enough`), so the answer
// is its answer. Most of a sphere's samples are skipped: its rational parametrisation slides
// along the surface (the parametric error over δ) only towards the triangle's middle.
constexpr double kWithinSlack = 1e-12;  // of the net's reach: thousands of ulps
bool interpolationWithinFrom(const FaceSurface& surface, const std::vector<FaceVertex>& vs,
                             const std::array<uint32_t, 3>& t,
                             const std::array<glm::dvec3, 3>& s, int n, double limit,
                             double slack) {
  const glm::dvec3 &s0 = s[0], &s1 = s[1], &s2 = s[2];
  thread_local std::vector<glm::dvec2> uvBuffer;
  thread_local std::vector<glm::dvec3> onSurfaceBuffer;
  const size_t interior = size_t(n + 1) * size_t(n + 2) / 2;
  if (uvBuffer.size() < interior) uvBuffer.resize(interior), onSurfaceBuffer.resize(interior);
  glm::dvec2* const uvs = uvBuffer.data();
  const glm::dvec2 uv0 = vs[t[0]].uv, uv1 = vs[t[1]].uv, uv2 = vs[t[2]].uv;
  const std::vector<Weights>& weights = samplePlan(n).walk;
  size_t count = 0;
  for (const Weights& w : weights) uvs[count++] = w.a * uv0 + w.b * uv1 + w.c * uv2;
  surface.points(uvs, count, onSurfaceBuffer.data());
  const double skip = limit - slack;
  const double skip2 = skip > 0 ? skip * skip : -1.0;
  for (size_t next = 0; next < count; ++next) {
    const Weights& w = weights[next];
    const glm::dvec3 target = w.a * s0 + w.b * s1 + w.c * s2;
    const glm::dvec3 d = target - onSurfaceBuffer[next];
    if (glm::dot(d, d) <= skip2) continue;
    if (surface.distance(target, uvs[next], limit) > limit) return false;
  }
  return true;
}

std::array<glm::dvec3, 3> cornerSurfacePoints(const FaceSurface& surface,
                                              const std::vector<FaceVertex>& vs,
                                              const std::array<uint32_t, 3>& t) {
  return {surface.point(vs[t[0]].uv), surface.point(vs[t[1]].uv), surface.point(vs[t[2]].uv)};
}

}  // namespace

SampledDeviations sampledDeviations(const FaceSurface& surface, const std::vector<FaceVertex>& vs,
                                    const std::array<uint32_t, 3>& t, int n) {
  return sampledDeviationsFrom(surface, vs, t, cornerSurfacePoints(surface, vs, t), n);
}

std::vector<SampledDeviations> sampledDeviationsSharingSides(
    const FaceSurface& surface, const std::vector<FaceVertex>& vs,
    const std::vector<std::array<uint32_t, 3>>& triangles, int n) {
  SideSampleCache sides(3 * triangles.size());
  std::vector<SampledDeviations> out;
  out.reserve(triangles.size());
  for (const std::array<uint32_t, 3>& t : triangles)
    out.push_back(
        sampledDeviationsFrom(surface, vs, t, cornerSurfacePoints(surface, vs, t), n, &sides));
  return out;
}

double parametricDeviation(const FaceSurface& surface, const std::vector<FaceVertex>& vs,
                           const std::array<uint32_t, 3>& t, int n) {
  return sampledDeviations(surface, vs, t, n).parametric;
}

double geometricDeviation(const FaceSurface& surface, const std::vector<FaceVertex>& vs,
                          const std::array<uint32_t, 3>& t, int n) {
  return largestOverSamples(vs, t, n, [&](const glm::dvec3& p, glm::dvec2 uv) {
    return surface.distance(p, uv);
  });
}

double interpolationDeviation(const FaceSurface& surface, const std::vector<FaceVertex>& vs,
                              const std::array<uint32_t, 3>& t, int n) {
  return sampledDeviations(surface, vs, t, n).interpolation;
}

double interpolationDistance(const FaceSurface& surface, const std::vector<FaceVertex>& vs,
                             const std::array<uint32_t, 3>& t, int n) {
  return interpolationDistanceFrom(surface, vs, t, cornerSurfacePoints(surface, vs, t), n,
                                   std::numeric_limits<double>::infinity());
}

bool interpolationWithin(const FaceSurface& surface, const std::vector<FaceVertex>& vs,
                         const std::array<uint32_t, 3>& t, int n, double limit) {
  return interpolationWithinFrom(surface, vs, t, cornerSurfacePoints(surface, vs, t), n, limit,
                                 kWithinSlack * surface.netReach());
}

double cornerOffset(const FaceSurface& surface, const std::vector<FaceVertex>& vs,
                    const std::array<uint32_t, 3>& t, std::vector<double>* known) {
  double worst = 0;
  for (uint32_t v : t) {
    if (vs[v].sharedId < 0) continue;
    if (!known) {
      worst = std::max(worst, glm::length(vs[v].position - surface.point(vs[v].uv)));
      continue;
    }
    double& offset = (*known)[v];
    if (offset < 0) offset = glm::length(vs[v].position - surface.point(vs[v].uv));
    worst = std::max(worst, offset);
  }
  return worst;
}

GapRefineResult refineGap(const FaceSurface& surface, std::vector<FaceVertex>& vs,
                 std::vector<FaceTriangle>& triangles, const std::vector<EdgeKey>& trimEdges,
                 const GapRefineOptions& options, std::vector<double>* parametric) {
  EdgeUsers users(triangles);
  CornerPoints onSurface(surface, vs);
  const auto isTrim = [&](uint32_t a, uint32_t b) {
    return std::binary_search(trimEdges.begin(), trimEdges.end(), edgeKey(a, b));
  };
  const glm::dvec2 metric = options.metric;
  const auto ratioOf = [&](const std::array<uint32_t, 3>& v) {
    return shapeRatio(vs[v[0]].uv * metric, vs[v[1]].uv * metric, vs[v[2]].uv * metric);
  };

  // t = (a, b, c) with a → b its longest side, s = (b, a, d) across it: (c, a, d) and (d, b, c)
  // when both are counter-clockwise and the thinner of them is kFlipSliverGain times as fat as
  // the thinner of t and s (so a flip is never undone).
  FlipFindings findings;  // for flipByDeviation, kept in step with every change below
  // t = (a, b, c) and s = (b, a, d) become (c, a, d) and (d, b, c): the side a → b becomes c → d.
  const auto flipEdge = [&](uint32_t t, uint32_t s, uint32_t a, uint32_t b, uint32_t c,
                            uint32_t d) {
    const std::array<uint32_t, 3> t2 = {c, a, d}, s2 = {d, b, c};
    triangles[t] = {t2, true};
    triangles[s] = {s2, true};
    findings.changed(t, t2), findings.changed(s, s2);
    users.erase(a, b);
    users.replace(a, d, s, t);
    users.replace(b, c, t, s);
    users.add(c, d, t), users.add(c, d, s);
  };
  const auto flipSliver = [&](uint32_t t, int longest) {
    const std::array<uint32_t, 3> v = rotated(triangles[t].v, longest);
    const uint32_t a = v[0], b = v[1], c = v[2];
    const SmallIdList sideUsers = users.of(a, b);
    size_t others = 0;  // the triangles across: those of the side other than t
    uint32_t s = 0;
    for (size_t k = 0; k < sideUsers.size(); ++k)
      if (sideUsers[k] != t) s = sideUsers[k], ++others;
    if (others != 1) return false;
    const int k = sideOf(triangles[s].v, a, b);
    const uint32_t d = triangles[s].v[(k + 2) % 3];
    if (d == c) return false;
    const std::array<uint32_t, 3> t2 = {c, a, d}, s2 = {d, b, c};
    const double before = std::min(ratioOf(v), ratioOf(triangles[s].v));
    if (!(std::min(ratioOf(t2), ratioOf(s2)) > kFlipSliverGain * std::max(before, 0.0)))
      return false;
    flipEdge(t, s, a, b, c, d);
    return true;
  };

  const auto splitSide = [&](uint32_t a, uint32_t b) {
    const glm::dvec2 uv = 0.5 * (vs[a].uv + vs[b].uv);
    vs.push_back({uv, surface.point(uv), -1});
    const uint32_t m = uint32_t(vs.size() - 1);
    onSurface.addOnSurface(m);
    const SmallIdList sideUsers = users.of(a, b);  // a copy: the loop changes the map
    for (size_t k = 0; k < sideUsers.size(); ++k) {
      const uint32_t u = sideUsers[k];
      // (p, q, r) with p → q the side → (p, m, r) and (m, q, r): the same orientation.
      const std::array<uint32_t, 3> w = rotated(triangles[u].v, sideOf(triangles[u].v, a, b));
      const uint32_t p = w[0], q = w[1], r = w[2], n = uint32_t(triangles.size());
      triangles[u].v = {p, m, r};
      triangles.push_back({{m, q, r}, triangles[u].gap});
      findings.changed(u, triangles[u].v), findings.changed(n, triangles[n].v);
      users.replace(q, r, u, n);
      users.add(p, m, u), users.add(m, r, u);
      users.add(m, r, n), users.add(m, q, n);
    }
    users.erase(a, b);
  };

  const auto addCentre = [&](uint32_t t) {
    const std::array<uint32_t, 3> v = triangles[t].v;
    const glm::dvec2 uv = (vs[v[0]].uv + vs[v[1]].uv + vs[v[2]].uv) / 3.0;
    vs.push_back({uv, surface.point(uv), -1});
    const uint32_t m = uint32_t(vs.size() - 1), n1 = uint32_t(triangles.size()), n2 = n1 + 1;
    onSurface.addOnSurface(m);
    triangles[t] = {{v[0], v[1], m}, true};
    triangles.push_back({{v[1], v[2], m}, true});
    triangles.push_back({{v[2], v[0], m}, true});
    findings.changed(t, triangles[t].v), findings.changed(n1, triangles[n1].v);
    findings.changed(n2, triangles[n2].v);
    users.replace(v[1], v[2], t, n1);
    users.replace(v[2], v[0], t, n2);
    users.add(v[0], m, t), users.add(v[0], m, n2);
    users.add(v[1], m, t), users.add(v[1], m, n1);
    users.add(v[2], m, n1), users.add(v[2], m, n2);
  };

  // Vertices never move, so a triangle's measures depend on its corners alone: each is taken
  // once per set of corners (a triangle left alone by a round, or rebuilt by a flip back, is
  // not sampled again).
  // m.geometric is only compared with δ: its check stops at the first sample over δ.
  // Sized by the gap triangles, the only ones measured: sized by all of the face's triangles
  // (kept ones included, ~60% of them on the IDF library) the two tables were ~4x too large,
  // and a robin map's reserve writes every bucket (~40 MB a corpus run at 1e-4, page faults).
  const size_t gapTriangles = size_t(std::count_if(
      triangles.begin(), triangles.end(), [](const FaceTriangle& t) { return t.gap; }));
  MeasureCache cache(2 * gapTriangles);
  SideSampleCache sides(3 * gapTriangles);
  // interpolationWithinFrom's allowance for the rounding of two evaluations of one S(uv).
  const double slack = kWithinSlack * surface.netReach();
  const bool geometric = options.measure == GapMeasure::Geometric;
  const auto deviation = [&](const std::array<uint32_t, 3>& v) {
    Measures& m = cache.of(v);
    if (!m.ordered) m.order = v, m.ordered = true;
    if (m.sampled.interpolation < 0)
      m.sampled = sampledDeviationsFrom(surface, vs, m.order, onSurface.of(m.order),
                                        options.subdivisions, &sides);
    return m.sampled.interpolation;
  };
  // Whether deviation(v) ≥ limit is certain from its cached measure or, not measured yet, from
  // its sides' terms already sampled (interpolationFromKnownSides) or a few inner samples
  // (interpolationProbeReaches, in the order deviation(v) would take them; that order is then
  // kept for it, since the measure skipped here would have been taken in it): false says nothing.
  const auto deviationAtLeast = [&](const std::array<uint32_t, 3>& v, double limit) {
    const Measures* m = cache.find(v);
    if (m && m->sampled.interpolation >= 0) return m->sampled.interpolation >= limit;
    if (interpolationFromKnownSides(vs, v, onSurface.of(v), options.subdivisions, sides) >= limit)
      return true;
    const std::array<uint32_t, 3> order = m && m->ordered ? m->order : v;
    if (!interpolationProbeReaches(surface, vs, order, onSurface.of(order), options.subdivisions,
                                   limit))
      return false;
    Measures& kept = cache.of(v);
    if (!kept.ordered) kept.order = order, kept.ordered = true;
    return true;
  };
  const auto withinTolerance = [&](const std::array<uint32_t, 3>& v) {
    if (deviation(v) <= options.tolerance) return true;
    if (!geometric) return false;
    Measures& m = cache.of(v);
    if (m.geometric < 0)
      m.geometric = interpolationWithinFrom(surface, vs, v, onSurface.of(v), options.subdivisions,
                                            options.tolerance, slack)
                        ? 0.0
                        : std::numeric_limits<double>::infinity();
    return m.geometric <= options.tolerance;
  };

  // Flips towards less deviation (a data-dependent triangulation, Dyn, Levin & Rippa 1990):
  // the gap's Delaunay triangulation in (u, v) joins points across a curved direction that a
  // ruled one would not (a fillet's two sides); a gap edge between two gap triangles is flipped
  // when the worse of the two new triangles deviates less than 0.9 of the worse old one (the
  // margin keeps rounding from flipping back and forth). Passes until none flips, at most 8.
  // A pass judges the edges shared at its start, in increasing order (a flip changes what the
  // edges after it see). Of those, only the ones that may be judged anew: the pending edges
  // (FlipFindings), and the ones ahead that a flip of this pass changes. Whether an edge was
  // shared at the start is its count now unless a flip of this pass changed that count (it
  // erases one edge and adds one), which is noted before the change.
  const auto bothGap = [&](const SmallIdList& ts) {
    return triangles[ts[0]].gap && triangles[ts[1]].gap;
  };
  HashMap<uint64_t, bool> sharedAtStart;
  std::vector<uint64_t> ahead;  // a min-heap
  uint64_t judging = 0;         // the key being judged
  const auto noteCount = [&](uint32_t a, uint32_t b) {
    sharedAtStart.emplace(FlipFindings::key(edgeKey(a, b)), users.of(a, b).size() == 2);
  };
  const auto queueIfAhead = [&](const std::array<uint32_t, 3>& v) {
    for (int k = 0; k < 3; ++k) {
      const EdgeKey e = edgeKey(v[k], v[(k + 1) % 3]);
      const uint64_t key = FlipFindings::key(e);
      if (key <= judging) continue;
      const auto noted = sharedAtStart.find(key);
      if (noted != sharedAtStart.end() ? noted->second : users.of(e.first, e.second).size() == 2) {
        ahead.push_back(key);
        std::push_heap(ahead.begin(), ahead.end(), std::greater<uint64_t>());
      }
    }
  };
  // The flip of the gap edge a → b between t = (a, b, c) and s (d across it), if it pays.
  const auto flipIfLessDeviation = [&](const EdgeKey& edge, uint32_t t, uint32_t s) {
    const std::array<uint32_t, 3> v = rotated(triangles[t].v,
                                              sideOf(triangles[t].v, edge.first, edge.second));
    const uint32_t a = v[0], b = v[1], c = v[2];
    const int k = sideOf(triangles[s].v, a, b);
    const uint32_t d = triangles[s].v[(k + 2) % 3];
    if (d == c) return false;
    const std::array<uint32_t, 3> t2 = {c, a, d}, s2 = {d, b, c};
    if (!(ratioOf(t2) >= 1e-5 && ratioOf(s2) >= 1e-5)) return false;  // ccw and not flat
    const double before = std::max(deviation(v), deviation(triangles[s].v));
    if (before <= options.tolerance) return false;  // nothing to gain for the refinement
    // Both new triangles must deviate less than 0.9 of the worse old one. Nearly every flip
    // fails on t2 alone (s2 is then not sampled), often already on the side terms t2 shares
    // with t and s, sampled with them (t2 is then not sampled either), or on a few of t2's
    // inner samples near its centre (the rest of it is then not sampled). A triangle left
    // unsampled here is sampled, to the same doubles, if it is ever made.
    const double limit = 0.9 * before;
    if (deviationAtLeast(t2, limit)) return false;
    const double t2Deviation = deviation(t2);
    if (!(t2Deviation < limit)) return false;
    if (!(std::max(t2Deviation, deviation(s2)) < limit)) return false;
    noteCount(a, b), noteCount(c, d);  // the two counts the flip changes
    flipEdge(t, s, a, b, c, d);
    return true;
  };
  const auto flipByDeviation = [&]() {
    size_t flips = 0;
    for (int pass = 0; pass < 8; ++pass) {
      size_t passFlips = 0;
      // Only edges between two gap triangles can flip, and a pass does not change which those
      // are (it flips only such edges): the rest, most of a face's edges, are left out before
      // the sort instead of skipped one by one (the same edges judged in the same order).
      std::vector<uint64_t> pending =
          findings.takePending([&] { return users.sharedEdges(bothGap); });
      pending.erase(std::remove_if(pending.begin(), pending.end(),
                                   [&](uint64_t key) {
                                     const EdgeKey e = FlipFindings::edgeOf(key);
                                     const SmallIdList ts = users.of(e.first, e.second);
                                     return ts.size() != 2 || !bothGap(ts);
                                   }),
                    pending.end());
      sharedAtStart.clear(), ahead.clear();
      size_t next = 0;
      bool any = false;
      while (next < pending.size() || !ahead.empty()) {
        uint64_t key;
        if (!ahead.empty() && (next == pending.size() || ahead.front() <= pending[next])) {
          key = ahead.front();
          std::pop_heap(ahead.begin(), ahead.end(), std::greater<uint64_t>());
          ahead.pop_back();
        } else {
          key = pending[next++];
        }
        if (any && key == judging) continue;  // queued twice
        judging = key, any = true;
        const EdgeKey edge = FlipFindings::edgeOf(key);
        if (isTrim(edge.first, edge.second)) continue;
        const SmallIdList ts = users.of(edge.first, edge.second);
        if (ts.size() != 2 || !triangles[ts[0]].gap || !triangles[ts[1]].gap) continue;
        if (findings.stillNoFlip(edge, ts[0], ts[1])) continue;
        if (flipIfLessDeviation(edge, ts[0], ts[1])) {
          ++passFlips;
          queueIfAhead(triangles[ts[0]].v), queueIfAhead(triangles[ts[1]].v);
        } else {
          findings.noFlip(edge);
        }
      }
      flips += passFlips;
      if (passFlips == 0) break;
    }
    return flips;
  };

  size_t changes = flipByDeviation();
  bool finished = false;
  for (int round = 0; round < options.maxRounds; ++round) {
    bool any = false;
    const size_t count = triangles.size();  // the pieces made this round wait for the next
    for (uint32_t t = 0; t < count; ++t) {
      if (!triangles[t].gap || withinTolerance(triangles[t].v)) continue;
      const std::array<uint32_t, 3> v = triangles[t].v;
      int longest = -1, split = -1;
      double longestLength = -1, splitScore = -1;
      for (int k = 0; k < 3; ++k) {
        const uint32_t a = v[k], b = v[(k + 1) % 3];
        const double length = glm::length((vs[a].uv - vs[b].uv) * metric);
        if (length > longestLength) longest = k, longestLength = length;
        if (isTrim(a, b)) continue;
        // The side whose midpoint is farthest from its chord (the surface bends along it): on a
        // cylinder the rulings are straight and the arcs are not, so the longest side in (u, v)
        // is often the wrong one. The length breaks ties (a flat surface, error inside).
        const glm::dvec2 mid = 0.5 * (vs[a].uv + vs[b].uv);
        const glm::dvec3 chord = 0.5 * (onSurface(a) + onSurface(b));
        const double sag = geometric ? surface.distance(chord, mid)
                                     : glm::length(surface.point(mid) - chord);
        const double score = sag + 1e-9 * length;
        if (score > splitScore) split = k, splitScore = score;
      }
      if (ratioOf(v) < kFlipSliverRatio && !isTrim(v[longest], v[(longest + 1) % 3]) &&
          flipSliver(t, longest)) {
        ++changes, any = true;
        continue;
      }
      if (split < 0)
        addCentre(t);
      else
        splitSide(v[split], v[(split + 1) % 3]);
      ++changes, any = true;
    }
    if (!any) {
      finished = true;
      break;
    }
    changes += flipByDeviation();
  }
  // Out of rounds: the last round's pieces were never judged.
  size_t unfinished = 0;
  if (!finished)
    for (const FaceTriangle& t : triangles)
      if (t.gap && !withinTolerance(t.v)) ++unfinished;
  if (parametric) {
    parametric->assign(triangles.size(), -1.0);
    for (size_t t = 0; t < triangles.size(); ++t)
      if (const Measures* m = triangles[t].gap ? cache.find(triangles[t].v) : nullptr)
        (*parametric)[t] = m->sampled.parametric;
  }
  return {changes, unfinished};
}

}  // namespace tessera::trim_detail
