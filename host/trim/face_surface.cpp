#include "trim/face_surface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <limits>
#include <type_traits>

#include "geometry/bezier.h"
#include "geometry/closest_point.h"
#include "geometry/fixed_degrees.h"
#include "geometry/general_patch.h"
#include "geometry/rational.h"

namespace tessera {
namespace {

// B_i,d(t) for i = 0..degree by the recurrence of bernsteinTriangle, in place (each value is
// the same expression of the same operands, so the same double). Degree ≥ 0: fixed at compile
// time (the loops unroll and the row stays in registers), −1: `degree` at run time.
template <int Degree = -1>
std::array<double, kMaxDegree + 1> bernsteinRow(int degree, double t) {
  if constexpr (Degree >= 0) degree = Degree;
  std::array<double, kMaxDegree + 1> b{};
  const double s = 1.0 - t;
  b[0] = 1.0;
  for (int d = 1; d <= degree; ++d) {
    b[d] = t * b[d - 1];
    for (int i = d - 1; i >= 1; --i) b[i] = s * b[i] + t * b[i - 1];
    b[0] = s * b[0];
  }
  return b;
}

// Σ_i B_i,n(u) Σ_j B_j,m(v) net[i·(m+1) + j], summed in tensorPartial's order (a = b = 0:
// its factor is 1·1), without its copies of the whole net: the deviation measure's hot path.
// N, M ≥ 0 fix the degrees at compile time, the same operations in the same order (the build
// contracts no multiply-add, -ffp-contract=off), so the same doubles as the run-time loop.
template <int N, int M, class Point>
Point tensorPointOfDegree(const Point* net, int n, int m, double u, double v) {
  if constexpr (N >= 0) n = N;
  if constexpr (M >= 0) m = M;
  const std::array<double, kMaxDegree + 1> bu = bernsteinRow<N>(n, u), bv = bernsteinRow<M>(m, v);
  Point sum(0.0);
  for (int i = 0; i <= n; ++i) {
    Point row(0.0);
    for (int j = 0; j <= m; ++j) row += bv[j] * net[i * (m + 1) + j];
    sum += bu[i] * row;
  }
  return sum;
}

template <class Point>
Point tensorPoint(const Point* net, int n, int m, double u, double v) {
  return withFixedDegrees(n, m, [&](auto N, auto M) {
    return tensorPointOfDegree<decltype(N)::value, decltype(M)::value>(net, n, m, u, v);
  });
}

// tensorPoint at (us[k], v), k = 0..2: one v, so the Bernstein row in v and the inner sums (one
// per row of the net) are taken once for the three; each result is tensorPoint's double (the
// same operations on the same operands).
template <int N, int M, class Point>
std::array<Point, 3> tensorPointsOfDegree(const Point* net, int n, int m,
                                          const std::array<double, 3>& us, double v) {
  if constexpr (N >= 0) n = N;
  if constexpr (M >= 0) m = M;
  const std::array<double, kMaxDegree + 1> bv = bernsteinRow<M>(m, v);
  std::array<Point, kMaxDegree + 1> rows;
  for (int i = 0; i <= n; ++i) {
    Point row(0.0);
    for (int j = 0; j <= m; ++j) row += bv[j] * net[i * (m + 1) + j];
    rows[i] = row;
  }
  std::array<Point, 3> out;
  for (int k = 0; k < 3; ++k) {
    const std::array<double, kMaxDegree + 1> bu = bernsteinRow<N>(n, us[k]);
    Point sum(0.0);
    for (int i = 0; i <= n; ++i) sum += bu[i] * rows[i];
    out[k] = sum;
  }
  return out;
}

template <class Point>
std::array<Point, 3> tensorPoints(const Point* net, int n, int m, const std::array<double, 3>& us,
                                  double v) {
  return withFixedDegrees(n, m, [&](auto N, auto M) {
    return tensorPointsOfDegree<decltype(N)::value, decltype(M)::value>(net, n, m, us, v);
  });
}

// FaceSurface::localUv, here so that point() inlines it: called, its result went through the
// stack as two scalars and came back as one vector load that waited on both stores (a quarter
// of point()'s time in perf).
inline glm::dvec2 localUvOf(const BezierPatchPiece& p, glm::dvec2 uv) {
  return glm::clamp(glm::dvec2((uv.x - p.u0) / (p.u1 - p.u0), (uv.y - p.v0) / (p.v1 - p.v0)),
                    0.0, 1.0);
}

}  // namespace

FaceSurface::FaceSurface(const TrimmedFace& face) : face_(&face) {
  // patchPoint converts a rational patch to its homogeneous form on every call; the mesher
  // evaluates each face tens of thousands of times, so convert once (same arithmetic after).
  checked_ = true;
  for (const BezierPatchPiece& p : face.pieces)
    try {
      validateTessellationPatch(p.patch, "piece");
    } catch (const std::invalid_argument&) {
      checked_ = false;
    }
  for (const BezierPatchPiece& p : face.pieces)
    for (const glm::dvec3& c : p.patch.cp)
      netReach_ = std::max({netReach_, std::abs(c.x), std::abs(c.y), std::abs(c.z)});
  rational_.resize(face.pieces.size());
  for (size_t k = 0; k < face.pieces.size(); ++k)
    if (!face.pieces[k].patch.weights.empty()) rational_[k] = toRationalPatch(face.pieces[k].patch);
  for (const BezierPatchPiece& p : face.pieces) {
    us_.push_back(p.u0), us_.push_back(p.u1);
    vs_.push_back(p.v0), vs_.push_back(p.v1);
  }
  for (auto* sides : {&us_, &vs_}) {
    std::sort(sides->begin(), sides->end());
    sides->erase(std::unique(sides->begin(), sides->end()), sides->end());
  }
  if (us_.size() < 2 || vs_.size() < 2) return;
  const size_t cellsV = vs_.size() - 1;
  cellPiece_.assign((us_.size() - 1) * cellsV, -1);
  for (size_t k = 0; k < face.pieces.size(); ++k) {
    const BezierPatchPiece& p = face.pieces[k];
    const size_t i0 = std::lower_bound(us_.begin(), us_.end(), p.u0) - us_.begin();
    const size_t i1 = std::lower_bound(us_.begin(), us_.end(), p.u1) - us_.begin();
    const size_t j0 = std::lower_bound(vs_.begin(), vs_.end(), p.v0) - vs_.begin();
    const size_t j1 = std::lower_bound(vs_.begin(), vs_.end(), p.v1) - vs_.begin();
    for (size_t i = i0; i < i1; ++i)
      for (size_t j = j0; j < j1; ++j) cellPiece_[i * cellsV + j] = int(k);
  }
}

size_t FaceSurface::cellOf(const std::vector<double>& sides, double x) {
  const size_t i = std::upper_bound(sides.begin(), sides.end(), x) - sides.begin();
  return std::clamp(i, size_t(1), sides.size() - 1) - 1;
}

size_t FaceSurface::pieceAt(glm::dvec2 uv) const {
  // One piece (a plane, most CAD faces): the only cell, or the nearest rectangle, is piece 0.
  if (face_->pieces.size() == 1) return 0;
  if (!cellPiece_.empty()) {
    const int piece = cellPiece_[cellOf(us_, uv.x) * (vs_.size() - 1) + cellOf(vs_, uv.y)];
    if (piece >= 0) return size_t(piece);
  }
  size_t best = 0;  // a hole in the grid of pieces: the nearest rectangle
  double bestDistance = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < face_->pieces.size(); ++k) {
    const BezierPatchPiece& p = face_->pieces[k];
    const glm::dvec2 clamped(std::clamp(uv.x, p.u0, p.u1), std::clamp(uv.y, p.v0, p.v1));
    const double d = glm::length(clamped - uv);
    if (d < bestDistance) best = k, bestDistance = d;
  }
  return best;
}

size_t FaceSurface::commonPiece(const glm::dvec2* uvs, size_t count) const {
  if (face_->pieces.size() == 1) return 0;
  // The uvs' box in one cell of the pieces' grid: every uv is in that cell (a cell index is
  // monotone in each coordinate), so pieceAt gives them all its piece, without a search per uv
  // (the refinement's samples: 42 of them a triangle, two binary searches each).
  glm::dvec2 lo = uvs[0], hi = uvs[0];
  bool ordered = true;  // no NaN: pieceAt's answer for one is not the box's
  for (size_t k = 0; k < count; ++k) {
    const glm::dvec2 uv = uvs[k];
    ordered = ordered && uv.x == uv.x && uv.y == uv.y;
    lo = glm::min(lo, uv), hi = glm::max(hi, uv);
  }
  if (ordered && !cellPiece_.empty()) {
    const size_t i = cellOf(us_, lo.x), j = cellOf(vs_, lo.y);
    const int piece = cellPiece_[i * (vs_.size() - 1) + j];
    if (piece >= 0 && cellOf(us_, hi.x) == i && cellOf(vs_, hi.y) == j) return size_t(piece);
  }
  const size_t index = pieceAt(uvs[0]);
  for (size_t k = 1; k < count; ++k)
    if (pieceAt(uvs[k]) != index) return kNoPiece;
  return index;
}

bool FaceSurface::piecesInBox(const glm::dvec2* uvs, size_t count,
                              std::vector<size_t>& pieces) const {
  if (cellPiece_.empty()) return false;
  glm::dvec2 lo = uvs[0], hi = uvs[0];
  for (size_t k = 0; k < count; ++k) {
    const glm::dvec2 uv = uvs[k];
    if (!(uv.x == uv.x && uv.y == uv.y)) return false;  // NaN: pieceAt's own answer
    lo = glm::min(lo, uv), hi = glm::max(hi, uv);
  }
  const size_t i0 = cellOf(us_, lo.x), i1 = cellOf(us_, hi.x);
  const size_t j0 = cellOf(vs_, lo.y), j1 = cellOf(vs_, hi.y);
  const size_t cellsV = vs_.size() - 1;
  for (size_t i = i0; i <= i1; ++i)  // a hole in the grid: pieceAt's nearest rectangle
    for (size_t j = j0; j <= j1; ++j)
      if (cellPiece_[i * cellsV + j] < 0) return false;
  pieces.resize(count);
  for (size_t k = 0; k < count; ++k) {
    // cellOf is monotone, so a uv's cell lies in the box's range: the last side of the range
    // at or below its coordinate, as cellOf's search finds it.
    size_t i = i0, j = j0;
    while (i < i1 && us_[i + 1] <= uvs[k].x) ++i;
    while (j < j1 && vs_[j + 1] <= uvs[k].y) ++j;
    pieces[k] = size_t(cellPiece_[i * cellsV + j]);
  }
  return true;
}

glm::dvec2 FaceSurface::localUv(size_t piece, glm::dvec2 uv) const {
  return localUvOf(face_->pieces[piece], uv);
}

glm::dvec2 FaceSurface::faceUv(size_t piece, glm::dvec2 local) const {
  const BezierPatchPiece& p = face_->pieces[piece];
  return {p.u0 + local.x * (p.u1 - p.u0), p.v0 + local.y * (p.v1 - p.v0)};
}

glm::dvec3 FaceSurface::point(glm::dvec2 uv) const { return pointOnPiece(pieceAt(uv), uv); }

glm::dvec3 FaceSurface::pointOnPiece(size_t piece, glm::dvec2 uv) const {
  const glm::dvec2 local = localUvOf(face_->pieces[piece], uv);
  // The pieces passed validateTessellationPatch (degrees ≤ kMaxDegree, finite, weights ≥ 0)
  // before the mesher measures them; a face built otherwise takes patchPoint's checked path.
  if (!checked_) return patchPoint(face_->pieces[piece].patch, local.x, local.y);
  const BezierPatch& patch = face_->pieces[piece].patch;
  if (rational_[piece]) {
    const RationalBezierPatch& r = *rational_[piece];
    const glm::dvec4 h = tensorPoint(r.cpw.data(), r.degreeU, r.degreeV, local.x, local.y);
    if (h.w == 0.0 || !std::isfinite(h.w))  // patchPoint's error, with its message
      return rationalPatchPoint(r, local.x, local.y);
    return glm::dvec3(h) / h.w;
  }
  return tensorPoint(patch.cp.data(), patch.degreeU, patch.degreeV, local.x, local.y);
}

void FaceSurface::points(const glm::dvec2* uvs, size_t count, glm::dvec3* out) const {
  const auto oneByOne = [&] {
    for (size_t k = 0; k < count; ++k) out[k] = point(uvs[k]);
  };
  if (!checked_ || count == 0) return oneByOne();
  // Every uv in one piece (a triangle's samples nearly always are): that piece's loop.
  const size_t index = commonPiece(uvs, count);
  if (index == kNoPiece) {
    // Across pieces' sides: each uv's piece from the few cells of the batch's box.
    thread_local std::vector<size_t> pieces;
    if (!piecesInBox(uvs, count, pieces)) return oneByOne();
    for (size_t k = 0; k < count; ++k) out[k] = pointOnPiece(pieces[k], uvs[k]);
    return;
  }
  const BezierPatchPiece& piece = face_->pieces[index];
  const BezierPatch& patch = piece.patch;
  if (!rational_[index]) {
    withFixedDegrees(patch.degreeU, patch.degreeV, [&](auto N, auto M) {
      for (size_t k = 0; k < count; ++k) {
        const glm::dvec2 local = localUvOf(piece, uvs[k]);
        out[k] = tensorPointOfDegree<decltype(N)::value, decltype(M)::value>(
            patch.cp.data(), patch.degreeU, patch.degreeV, local.x, local.y);
      }
    });
    return;
  }
  const RationalBezierPatch& r = *rational_[index];
  withFixedDegrees(r.degreeU, r.degreeV, [&](auto N, auto M) {
    for (size_t k = 0; k < count; ++k) {
      const glm::dvec2 local = localUvOf(piece, uvs[k]);
      const glm::dvec4 h = tensorPointOfDegree<decltype(N)::value, decltype(M)::value>(
          r.cpw.data(), r.degreeU, r.degreeV, local.x, local.y);
      out[k] = h.w == 0.0 || !std::isfinite(h.w) ? rationalPatchPoint(r, local.x, local.y)
                                                  : glm::dvec3(h) / h.w;
    }
  });
}

std::array<glm::dvec3, 3> FaceSurface::pointsAlongU(const std::array<glm::dvec2, 3>& uvs) const {
  const size_t piece = pieceAt(uvs[1]);
  const auto separately = [&] {  // the middle first, as meanScales called them
    const glm::dvec3 middle = point(uvs[1]);
    return std::array<glm::dvec3, 3>{point(uvs[0]), middle, point(uvs[2])};
  };
  if (!checked_ || uvs[0].y != uvs[1].y || uvs[2].y != uvs[1].y || pieceAt(uvs[0]) != piece ||
      pieceAt(uvs[2]) != piece)
    return separately();
  const BezierPatchPiece& p = face_->pieces[piece];
  std::array<double, 3> us;
  for (int k = 0; k < 3; ++k) us[k] = localUvOf(p, uvs[k]).x;
  const double v = localUvOf(p, uvs[1]).y;
  if (rational_[piece]) {
    const RationalBezierPatch& r = *rational_[piece];
    const std::array<glm::dvec4, 3> h = tensorPoints(r.cpw.data(), r.degreeU, r.degreeV, us, v);
    for (const glm::dvec4& hk : h)
      if (hk.w == 0.0 || !std::isfinite(hk.w)) return separately();  // point()'s error path
    return {glm::dvec3(h[0]) / h[0].w, glm::dvec3(h[1]) / h[1].w, glm::dvec3(h[2]) / h[2].w};
  }
  return tensorPoints(p.patch.cp.data(), p.patch.degreeU, p.patch.degreeV, us, v);
}

double FaceSurface::distance(const glm::dvec3& target, glm::dvec2 guess, double enough) const {
  const size_t piece = pieceAt(guess);
  if (checked_) {  // every piece passed validateTessellationPatch: no check per evaluation
    if (rational_[piece])
      return closestPointOnValidPatch(*rational_[piece], target, localUv(piece, guess), 12, enough)
          .distance;
    return closestPointOnValidPatch(face_->pieces[piece].patch, target, localUv(piece, guess), 12,
                                    enough)
        .distance;
  }
  if (rational_[piece])  // the homogeneous form converted once (the constructor)
    return closestPointOnPatch(*rational_[piece], target, localUv(piece, guess), 12, enough)
        .distance;
  return closestPointOnPatch(face_->pieces[piece].patch, target, localUv(piece, guess), 12, enough)
      .distance;
}

namespace {

// point() of a one-piece face at the stencils of FaceSurface::meanScales' grid, with the grid's
// shared coordinates taken once: a column's v values (vⱼ, vⱼ ± h) are every column's, so the
// Bernstein rows in v and the inner sums (one per row of the net) are taken once per v for all
// six columns, and the rows in u once per u. Each point is tensorPoint's double (the same
// operations on the same operands, as tensorPointsOfDegree), then point()'s division.
// Returns false where point() would take its error path (a weight sum 0 or not finite).
template <int N, int M, class Point, int G>
bool gridStencilOfDegree(const Point* net, int n, int m, const BezierPatchPiece& piece,
                         const std::array<double, 3 * G>& us, const std::array<double, 3 * G>& vs,
                         std::array<glm::dvec3, 5 * G * G>& out) {
  if constexpr (N >= 0) n = N;
  if constexpr (M >= 0) m = M;
  // us[3i + k], vs[3j + k]: the grid's i-th u (k = 1) and its neighbours (k = 0: − h, 2: + h).
  std::array<std::array<double, kMaxDegree + 1>, 3 * G> bu;
  for (size_t a = 0; a < us.size(); ++a)
    bu[a] = bernsteinRow<N>(n, localUvOf(piece, {us[a], vs[1]}).x);
  std::array<std::array<Point, kMaxDegree + 1>, 3 * G> rows;
  for (size_t b = 0; b < vs.size(); ++b) {
    const std::array<double, kMaxDegree + 1> bv = bernsteinRow<M>(m, localUvOf(piece, {us[1], vs[b]}).y);
    for (int i = 0; i <= n; ++i) {
      Point row(0.0);
      for (int j = 0; j <= m; ++j) row += bv[j] * net[i * (m + 1) + j];
      rows[b][i] = row;
    }
  }
  const auto at = [&](size_t a, size_t b, glm::dvec3& result) {
    Point sum(0.0);
    for (int i = 0; i <= n; ++i) sum += bu[a][i] * rows[b][i];
    if constexpr (std::is_same_v<Point, glm::dvec4>) {
      if (sum.w == 0.0 || !std::isfinite(sum.w)) return false;
      result = glm::dvec3(sum) / sum.w;
    } else {
      result = sum;
    }
    return true;
  };
  // out[5·(i·G + j) + k]: k = 0..2 along u (u − h, u, u + h), 3..4 along v (v − h, v + h).
  for (size_t i = 0; i < G; ++i)
    for (size_t j = 0; j < G; ++j) {
      glm::dvec3* o = &out[5 * (i * G + j)];
      if (!(at(3 * i, 3 * j + 1, o[0]) && at(3 * i + 1, 3 * j + 1, o[1]) &&
            at(3 * i + 2, 3 * j + 1, o[2]) && at(3 * i + 1, 3 * j, o[3]) &&
            at(3 * i + 1, 3 * j + 2, o[4])))
        return false;
    }
  return true;
}

}  // namespace

FaceSurface::Scales FaceSurface::meanScales(glm::dvec2 lo, glm::dvec2 hi) const {
  constexpr int kGrid = 6;
  const glm::dvec2 h = 1e-3 * (hi - lo);
  const glm::dvec2 du(h.x, 0), dv(0, h.y);
  // The grid's coordinates as meanScalesPointwise forms them: uv ± du keeps uv's v (x − 0 is
  // x, −0 included) and uv ± dv its u.
  std::array<double, 3 * kGrid> us, vs;
  for (int i = 0; i < kGrid; ++i) {
    const glm::dvec2 uv = lo + (hi - lo) * glm::dvec2((i + 0.5) / kGrid, (i + 0.5) / kGrid);
    us[3 * i] = (uv - du).x, us[3 * i + 1] = uv.x, us[3 * i + 2] = (uv + du).x;
    vs[3 * i] = (uv - dv).y, vs[3 * i + 1] = uv.y, vs[3 * i + 2] = (uv + dv).y;
  }
  std::array<glm::dvec3, 5 * kGrid * kGrid> stencil;
  bool gridded = false;
  if (checked_ && face_->pieces.size() == 1) {  // every uv in piece 0 (pieceAt)
    const BezierPatchPiece& piece = face_->pieces[0];
    if (rational_[0]) {
      const RationalBezierPatch& r = *rational_[0];
      gridded = withFixedDegrees(r.degreeU, r.degreeV, [&](auto N, auto M) {
        return gridStencilOfDegree<decltype(N)::value, decltype(M)::value, glm::dvec4, kGrid>(
            r.cpw.data(), r.degreeU, r.degreeV, piece, us, vs, stencil);
      });
    } else {
      const BezierPatch& patch = piece.patch;
      gridded = withFixedDegrees(patch.degreeU, patch.degreeV, [&](auto N, auto M) {
        return gridStencilOfDegree<decltype(N)::value, decltype(M)::value, glm::dvec3, kGrid>(
            patch.cp.data(), patch.degreeU, patch.degreeV, piece, us, vs, stencil);
      });
    }
  }
  return gridded ? scalesOf(stencil, h) : meanScalesPointwise(lo, hi);
}

FaceSurface::Scales FaceSurface::meanScalesPointwise(glm::dvec2 lo, glm::dvec2 hi) const {
  constexpr int kGrid = 6;
  const glm::dvec2 h = 1e-3 * (hi - lo);
  const glm::dvec2 du(h.x, 0), dv(0, h.y);
  // The points along v of the whole grid in one points() call, then the sums in grid order.
  std::array<glm::dvec2, 2 * kGrid * kGrid> alongV;
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      const glm::dvec2 uv = lo + (hi - lo) * glm::dvec2((i + 0.5) / kGrid, (j + 0.5) / kGrid);
      alongV[2 * (i * kGrid + j)] = uv - dv;
      alongV[2 * (i * kGrid + j) + 1] = uv + dv;
    }
  std::array<glm::dvec3, 2 * kGrid * kGrid> pointsV;
  points(alongV.data(), alongV.size(), pointsV.data());
  std::array<glm::dvec3, 5 * kGrid * kGrid> stencil;
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      const glm::dvec2 uv = lo + (hi - lo) * glm::dvec2((i + 0.5) / kGrid, (j + 0.5) / kGrid);
      const std::array<glm::dvec3, 3> alongU = pointsAlongU({uv - du, uv, uv + du});
      glm::dvec3* o = &stencil[5 * (i * kGrid + j)];
      o[0] = alongU[0], o[1] = alongU[1], o[2] = alongU[2];
      o[3] = pointsV[2 * (i * kGrid + j)], o[4] = pointsV[2 * (i * kGrid + j) + 1];
    }
  return scalesOf(stencil, h);
}

FaceSurface::Scales FaceSurface::scalesOf(const std::array<glm::dvec3, 5 * 36>& stencil,
                                          glm::dvec2 h) {
  constexpr int kGrid = 6;
  Scales sum{glm::dvec2(0.0), glm::dvec2(0.0)};
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      const glm::dvec3* o = &stencil[5 * (i * kGrid + j)];
      const glm::dvec3 &p = o[1], &pu0 = o[0], &pu1 = o[2];
      const glm::dvec3 &pv0 = o[3], &pv1 = o[4];
      if (h.x > 0) sum.speeds.x += glm::length(pu1 - pu0) / (2 * h.x);
      if (h.y > 0) sum.speeds.y += glm::length(pv1 - pv0) / (2 * h.y);
      const glm::dvec3 normal = glm::cross(pu1 - pu0, pv1 - pv0);
      const double length = glm::length(normal);
      if (!(length > 0)) continue;  // a pole, or a side of no width: no normal there
      sum.bending.x += std::abs(glm::dot(normal, pu1 - 2.0 * p + pu0)) / (length * h.x * h.x);
      sum.bending.y += std::abs(glm::dot(normal, pv1 - 2.0 * p + pv0)) / (length * h.y * h.y);
    }
  Scales mean{sum.speeds / double(kGrid * kGrid), sum.bending / double(kGrid * kGrid)};
  glm::dvec2& speeds = mean.speeds;
  const double floor = 1e-12 * std::max({speeds.x, speeds.y, 1e-300});
  if (!(speeds.x > floor)) speeds.x = std::max(floor, speeds.y);
  if (!(speeds.y > floor)) speeds.y = std::max(floor, speeds.x);
  return mean;
}

}  // namespace tessera
