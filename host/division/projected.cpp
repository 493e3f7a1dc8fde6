// The projected-grid bound and estimate (projected.h; proof and measurements in
// docs/realtime.md, "Counts"). With all weights W > 0, S = P/w is the image of the homogeneous
// net; c is the centre of the projected control points' bounding box and R their largest
// distance from it, so that in coordinates centred on c the image and every grid corner lie
// within R (convex hull). On a grid triangle the affine interpolant L of its corners' images
// gives e = L − S = N/w with N = w·L − P, a polynomial that vanishes at the three corners;
// Filip's bound of its own linear interpolation error (zero) bounds e, with
//   N_uu = w_uu·L + 2·w_u·L_u − P_uu,   N_uv = w_uv·L + w_u·L_v + w_v·L_u − P_uv,
// |L| ≤ R, |L_u| ≤ sup|S_u| (a triangle leg along u), w ≥ w_min.
#include "division/projected.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "division/detail/directional.h"

namespace tessera {
namespace {

// The net centred on c: (P − c·w, w) per control point, whose image is S − c; at most 4×4.
struct CentredNet {
  int n = 0, m = 0;
  std::array<glm::dvec3, 16> c{};
  double radius = 0, wMin = INFINITY;
  glm::dvec3& at(int i, int j) { return c[size_t(i * (m + 1) + j)]; }
  const glm::dvec3& at(int i, int j) const { return c[size_t(i * (m + 1) + j)]; }
  // sup over |s| ≤ R of ‖a.P − s·a.w‖ for a coefficient a of a derivative of (P, w): it bounds
  // that derivative of P − s·w for any point s of the image or of a triangle (convex hull).
  double hull(const glm::dvec3& a) const {
    return glm::length(glm::dvec2(a)) + radius * std::abs(a.z);
  }
};

// False when some W ≤ 0 (the net reaches the eye plane: no bound here). The radius is the
// bound's (hull()); the estimate does without it (`withRadius` false: 16 square roots saved).
bool centredNet(const glm::dvec4* net, int n, int m, CentredNet& out, bool withRadius) {
  if (n < 1 || n > 3 || m < 0 || m > 3)
    throw std::invalid_argument("projected division counts: degrees 1..3 (v: 0..3), got " +
                                std::to_string(n) + "×" + std::to_string(m));
  out.n = n;
  out.m = m;
  const int count = (n + 1) * (m + 1);
  glm::dvec2 lo(INFINITY), hi(-INFINITY);
  for (int k = 0; k < count; ++k) {
    if (!(net[k].w > 0.0)) return false;
    out.wMin = std::min(out.wMin, net[k].w);
    const glm::dvec2 p = glm::dvec2(net[k]) / net[k].w;
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::dvec2 centre = 0.5 * (lo + hi);
  for (int k = 0; k < count; ++k) {
    const glm::dvec4& h = net[k];
    if (withRadius) out.radius = std::max(out.radius, glm::length(glm::dvec2(h) / h.w - centre));
    out.c[size_t(k)] = glm::dvec3(h.x - centre.x * h.w, h.y - centre.y * h.w, h.w);
  }
  return true;
}

// First-order terms, from the hodographs' coefficients: G ≥ sup|S_u|, sup|S_v| (S_u = (P_u −
// w_u·S)/w), W ≥ sup|w_u|, sup|w_v|.
struct FirstOrder {
  double gu = 0, gv = 0, wu = 0, wv = 0;
};

FirstOrder firstOrder(const CentredNet& x) {
  FirstOrder f;
  for (int i = 0; i <= x.n; ++i)
    for (int j = 0; j <= x.m; ++j) {
      if (i < x.n) {
        const glm::dvec3 a = x.at(i + 1, j) - x.at(i, j);
        f.gu = std::max(f.gu, x.hull(a));
        f.wu = std::max(f.wu, std::abs(a.z));
      }
      if (j < x.m) {
        const glm::dvec3 a = x.at(i, j + 1) - x.at(i, j);
        f.gv = std::max(f.gv, x.hull(a));
        f.wv = std::max(f.wv, std::abs(a.z));
      }
    }
  f.gu *= x.n / x.wMin;
  f.gv *= x.m / x.wMin;
  f.wu *= x.n;
  f.wv *= x.m;
  return f;
}

// The derivative along u (or v) in the net's own degree: D_l = (n−l)(X_(l+1) − X_l) +
// l(X_l − X_(l−1)) (docs/rational_division.md, eq. D1), the hodograph elevated back to degree
// n; applied twice, the second partials in bidegree (n, m).
CentredNet degreeKeepingDerivative(const CentredNet& x, bool alongU) {
  CentredNet d = x;
  const int degree = alongU ? x.n : x.m, lines = alongU ? x.m + 1 : x.n + 1;
  const size_t step = alongU ? size_t(x.m + 1) : 1, lineStep = alongU ? 1 : size_t(x.m + 1);
  for (int line = 0; line < lines; ++line) {
    const size_t first = size_t(line) * lineStep;
    glm::dvec3 before(0.0);  // X_l − X_(l−1), zero at l = 0
    for (int l = 0; l <= degree; ++l) {
      const size_t at = first + size_t(l) * step;
      const glm::dvec3 after = l < degree ? x.c[at + step] - x.c[at] : glm::dvec3(0.0);
      d.c[at] = double(degree - l) * after + double(l) * before;
      before = after;
    }
  }
  return d;
}

// Counts from (uu, uv, vv) or, for the estimate, from a deviation function of the legs.
int toCount(double real, int maxPerDirection, Divisions& r) {
  if (!(real <= maxPerDirection)) {
    r.status = DivisionStatus::Capped;
    return maxPerDirection;
  }
  return int(std::ceil(real));
}

// The second partials of S = P/w, as triples (S_uu, S_uv, S_vv), two per coefficient of the
// net: the quotient rule applied to the coefficients of P, w and their derivatives in the net's
// own bidegree (degree-keeping derivatives), once as the affine interpolation's error sees
// S'' = (P'' − w''·S − 2·w'·S')/w and once as the perspective-correct one sees it,
// (P'' − w''·S)/w (docs/realtime.md, "Counts"). Exact at the corners, where these coefficients
// are the values; in the affine limit (all weights equal) the Bernstein coefficients of S''
// itself, whose convex hull holds S'' everywhere.
struct Triple {
  glm::dvec2 uu, uv, vv;

  // ‖a²·S_uu + 2ax·S_uv + x²·S_vv‖ along an edge (a, x) in (u, v).
  double along(double a, double x) const {
    return glm::length(a * a * uu + 2.0 * a * x * uv + x * x * vv);
  }
};

// The triples, kept twice: as Triples (the strips) and as coordinate arrays, which the cell
// estimate's loop runs over two or four at a time (the same arithmetic per triple).
struct SecondPartials {
  int count = 0;
  std::array<Triple, 32> t;  // the first `count` are set
  std::array<double, 32> uuX, uuY, uvX, uvY, vvX, vvY;
  double largestUu = 0, largestVv = 0;  // the largest ‖S_uu‖, ‖S_vv‖

  void set(size_t l, const Triple& triple) {
    t[l] = triple;
    uuX[l] = triple.uu.x, uuY[l] = triple.uu.y;
    uvX[l] = triple.uv.x, uvY[l] = triple.uv.y;
    vvX[l] = triple.vv.x, vvY[l] = triple.vv.y;
  }
};

// A curve's (m = 0) largest ‖S_uu‖ alone, all its count needs: secondPartials' arithmetic with
// the v derivatives zero, and no triples.
double curveLargestSecond(const CentredNet& x) {
  const CentredNet du = degreeKeepingDerivative(x, true), duu = degreeKeepingDerivative(du, true);
  double largest = 0;
  for (size_t l = 0; l <= size_t(x.n); ++l) {
    const double w = x.c[l].z;
    const glm::dvec2 p = glm::dvec2(x.c[l]) / w;
    const glm::dvec2 su = (glm::dvec2(du.c[l]) - du.c[l].z * p) / w;
    const glm::dvec2 uu = (glm::dvec2(duu.c[l]) - duu.c[l].z * p) / w;
    const glm::dvec2 affineUu = uu - 2.0 * du.c[l].z / w * su;
    largest = std::max({largest, glm::dot(affineUu, affineUu), glm::dot(uu, uu)});
  }
  return std::sqrt(largest);  // glm::length is sqrt(dot), and sqrt is monotone
}

SecondPartials secondPartials(const CentredNet& x) {
  const CentredNet du = degreeKeepingDerivative(x, true), dv = degreeKeepingDerivative(x, false);
  const CentredNet duu = degreeKeepingDerivative(du, true), duv = degreeKeepingDerivative(du, false),
                   dvv = degreeKeepingDerivative(dv, false);
  SecondPartials s;
  const size_t perSet = size_t((x.n + 1) * (x.m + 1));
  s.count = 2 * int(perSet);
  for (size_t l = 0; l < perSet; ++l) {
    const double w = x.c[l].z;
    const glm::dvec2 p = glm::dvec2(x.c[l]) / w;
    const glm::dvec2 su = (glm::dvec2(du.c[l]) - du.c[l].z * p) / w,
                     sv = (glm::dvec2(dv.c[l]) - dv.c[l].z * p) / w;
    const glm::dvec2 uu = (glm::dvec2(duu.c[l]) - duu.c[l].z * p) / w,
                     uv = (glm::dvec2(duv.c[l]) - duv.c[l].z * p) / w,
                     vv = (glm::dvec2(dvv.c[l]) - dvv.c[l].z * p) / w;
    const glm::dvec2 affineUu = uu - 2.0 * du.c[l].z / w * su,
                     affineUv = uv - (du.c[l].z * sv + dv.c[l].z * su) / w,
                     affineVv = vv - 2.0 * dv.c[l].z / w * sv;
    s.set(l, {affineUu, affineUv, affineVv});
    s.set(l + perSet, {uu, uv, vv});
    s.largestUu = std::max({s.largestUu, glm::dot(affineUu, affineUu), glm::dot(uu, uu)});
    s.largestVv = std::max({s.largestVv, glm::dot(affineVv, affineVv), glm::dot(vv, vv)});
  }
  s.largestUu = std::sqrt(s.largestUu);  // glm::length is sqrt(dot), and sqrt is monotone
  s.largestVv = std::sqrt(s.largestVv);
  return s;
}

// The estimated deviation of an h×k cell's triangles: for each triple taken as a constant
// second derivative H, ½·max over the triangle of Σ λ_i λ_j ‖e_ijᵀ H e_ij‖ (exact for constant
// H: the weighted-variance identity, division/directional.cpp) along the legs (h, 0), (0, k) and
// a diagonal (h, ±k): both diagonals, because the stitched pattern's strip triangles also run
// along the other one (docs/realtime.md). The largest over the triples. Only whether it exceeds
// `stopAbove` matters when that is finite: ½·Σ λλ c lies between max c/8 and max c/6, which
// settles most triples without the exact maximum.
// Square roots are taken only where needed: sqrt, /6 and /8 are monotone, so the largest of
// the square roots is the square root of the largest.
double estimatedCellDeviation(const SecondPartials& s, double h, double k, double stopAbove) {
  // Per triple: the squared norms along the legs and diagonals, and the largest of them.
  std::array<double, 32> legU, legV, plus2, minus2, most2;
  const double hh = h * h, hk = 2.0 * h * k, kk = k * k;
  const size_t count = size_t(s.count);
  for (size_t l = 0; l < count; ++l) {  // glm's arithmetic, written out per coordinate
    const double ax = hh * s.uuX[l], ay = hh * s.uuY[l], bx = hk * s.uvX[l], by = hk * s.uvY[l];
    const double dx = kk * s.vvX[l], dy = kk * s.vvY[l];
    const double px = ax + bx + dx, py = ay + by + dy, mx = ax - bx + dx, my = ay - by + dy;
    legU[l] = ax * ax + ay * ay;
    legV[l] = dx * dx + dy * dy;
    plus2[l] = px * px + py * py;
    minus2[l] = mx * mx + my * my;
    most2[l] = std::max(std::max(legU[l], legV[l]), std::max(plus2[l], minus2[l]));
  }
  // Four running maxima, not one chain (NaNs drop out of std::max(largest, NaN) in any order).
  std::array<double, 4> lanes{};
  for (size_t l = 0; l < count; ++l) lanes[l % 4] = std::max(lanes[l % 4], most2[l]);
  const double largest2 = std::max(std::max(lanes[0], lanes[1]), std::max(lanes[2], lanes[3]));
  const double settled = std::sqrt(largest2) / 8.0, largest = std::sqrt(largest2) / 6.0;
  if (std::isfinite(stopAbove)) {
    if (largest <= stopAbove) return largest;
    if (settled > stopAbove) return settled;
  }
  // A triple whose sqrt(most²)/6 is not above the worst so far cannot raise it. Below
  // (6·worst)²·(1 − 1e-12) that holds despite rounding, and the square root is skipped (no
  // skipping where that product overflows).
  auto skipBelowOf = [](double worst) {
    const double below = 36.0 * worst * worst * (1.0 - 1e-12);
    return below < INFINITY ? below : 0.0;
  };
  double worst = settled, skipBelow = skipBelowOf(worst);
  for (size_t l = 0; l < size_t(s.count); ++l)
    if (!(most2[l] < skipBelow) && std::sqrt(most2[l]) / 6.0 > worst) {
      const glm::dvec4 c = glm::sqrt(glm::dvec4(legU[l], legV[l], plus2[l], minus2[l]));
      worst = std::max({worst, 0.5 * largestSimplexProduct(c.x, c.y, c.z),
                        0.5 * largestSimplexProduct(c.x, c.y, c.w)});
      skipBelow = skipBelowOf(worst);
    }
  return worst;
}

// The triples of the two coefficient rows (or columns) next to side `side` (V0, U1, V1, U0):
// S'' near that side.
SecondPartials sideTriples(const CentredNet& x, const SecondPartials& s, int side) {
  SecondPartials near;
  const int perSet = (x.n + 1) * (x.m + 1);
  for (int set = 0; set < s.count / perSet; ++set)
    for (int i = 0; i <= x.n; ++i)
      for (int j = 0; j <= x.m; ++j) {
        const bool keep = side == 0   ? j <= 1
                          : side == 2 ? j >= x.m - 1
                          : side == 3 ? i <= 1
                                      : i >= x.n - 1;
        if (keep) near.t[size_t(near.count++)] = s.t[size_t(set * perSet + i * (x.m + 1) + j)];
      }
  return near;
}

// The estimated deviation of a strip triangle (o_k, o_(k+1), n_i) of a side whose edge has e
// segments: a base of b = 1/e along the side and its apex one inner row (k = 1/N) across, within
// half an inner segment d of the base's middle (the zipper rule, docs/realtime.md "The
// pattern"). The same constant-H maximum as estimatedCellDeviation over its three edges, with
// the apex at either end of that range.
double stripDeviation(const SecondPartials& s, bool alongU, double b, double k, double d) {
  double worst = 0.0;
  for (size_t l = 0; l < size_t(s.count); ++l) {
    const Triple& t = s.t[l];
    auto along = [&](double a, double x) { return alongU ? t.along(a, x) : t.along(x, a); };
    for (const double apex : {0.5 * b - d, 0.5 * b + d})
      worst = std::max(worst, 0.5 * largestSimplexProduct(along(b, 0.0), along(apex, k),
                                                           along(apex - b, k)));
  }
  return worst;
}

// A side whose edge asks for fewer segments e than the inner grid has along it gets strip
// triangles wider than the grid's cells, reaching one inner row into the patch. Where their
// estimate (on the triples next to the side) exceeds the tolerance, the count across is raised:
// at most doubled, since the edge's own count bounds the part along the side, which no count
// across can lower.
void fitStrips(const CentredNet& x, const SecondPartials& s, const std::array<int, 4>& segments,
               double tolerance, int maxPerDirection, Divisions& r) {
  for (int side = 0; side < 4; ++side) {
    const bool alongU = side % 2 == 0;
    const int e = segments[size_t(side)];
    int& across = alongU ? r.nv : r.nu;
    const int along = alongU ? r.nu : r.nv, limit = std::min(2 * across, maxPerDirection);
    if (e >= along) continue;
    const SecondPartials near = sideTriples(x, s, side);
    while (across < limit) {
      // One inner row across: 1/N, or ½ when N = 1 (the single line of the inner grid).
      const double deviation =
          stripDeviation(near, alongU, 1.0 / e, 1.0 / std::max(across, 2), 0.5 / along);
      if (deviation <= tolerance) break;
      across = std::min(limit, std::max(across + 1, int(std::ceil(across * std::sqrt(deviation / tolerance)))));
    }
  }
}

}  // namespace

SecondDerivativeBounds projectedGridBounds(const glm::dvec4* net, int degreeU, int degreeV) {
  SecondDerivativeBounds r;
  CentredNet x;
  if (!centredNet(net, degreeU, degreeV, x, true)) {
    r.bounded = false;
    r.uu = r.uv = r.vv = INFINITY;
    return r;
  }
  const int n = x.n, m = x.m;
  double d2u = 0, d2v = 0, duv = 0;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j) {
      const glm::dvec3& h = x.at(i, j);
      if (i + 1 < n) d2u = std::max(d2u, x.hull(x.at(i + 2, j) - 2.0 * x.at(i + 1, j) + h));
      if (j + 1 < m) d2v = std::max(d2v, x.hull(x.at(i, j + 2) - 2.0 * x.at(i, j + 1) + h));
      if (i < n && j < m)
        duv = std::max(duv, x.hull(x.at(i + 1, j + 1) - x.at(i + 1, j) - x.at(i, j + 1) + h));
    }
  const FirstOrder f = firstOrder(x);
  // Rounding: the sums above are of a few terms; 1e-12 keeps them from falling below the value.
  const double slack = (1.0 + 1e-12) / x.wMin;
  r.uu = (n * (n - 1) * d2u + 2.0 * f.wu * f.gu) * slack;
  r.uv = (n * m * duv + f.wu * f.gv + f.wv * f.gu) * slack;
  r.vv = (m * (m - 1) * d2v + 2.0 * f.wv * f.gv) * slack;
  return r;
}

Divisions estimatedProjectedDivisions(const glm::dvec4* net, int degreeU, int degreeV,
                                      double tolerance, int maxPerDirection,
                                      const std::array<int, 4>* sideSegments) {
  Divisions r;
  CentredNet x;
  if (!centredNet(net, degreeU, degreeV, x, false)) {
    r.status = DivisionStatus::Unbounded;
    r.bounds.bounded = false;
    r.nu = r.nv = maxPerDirection;
    r.realU = r.realV = INFINITY;
    return r;
  }
  if (x.m == 0) {  // a curve: a segment's midpoint deviates ‖C''‖·h²/8, nothing else
    r.realU = std::max(1.0, std::sqrt(curveLargestSecond(x) / (8.0 * tolerance)));
    r.nu = toCount(r.realU, maxPerDirection, r);
    return r;
  }
  const SecondPartials s = secondPartials(x);
  const double largestUu = s.largestUu, largestVv = s.largestVv;
  // The counts each direction needs alone (a leg's midpoint deviates ‖S''‖·leg²/8), then both
  // scaled up together until the diagonals and the triangles' interiors pass too (the
  // deviation scales with the square of the legs).
  double nu = std::max(1.0, std::sqrt(largestUu / (8.0 * tolerance)));
  double nv = std::max(1.0, std::sqrt(largestVv / (8.0 * tolerance)));
  const double e = estimatedCellDeviation(s, 1.0 / nu, 1.0 / nv, INFINITY);
  if (e > tolerance) {
    const double scale = std::sqrt(e / tolerance);
    nu *= scale;
    nv *= scale;
  }
  r.realU = nu;
  r.realV = nv;
  r.nu = toCount(nu, maxPerDirection, r);
  r.nv = toCount(nv, maxPerDirection, r);
  if (r.status != DivisionStatus::Ok) return r;
  // Rounding both up wastes up to a row and a column: the neighbours with one count lower (and,
  // to keep the product down, the other one higher) are tried, smallest product first.
  const int nu0 = r.nu, nv0 = r.nv;
  std::array<std::pair<int, int>, 4> candidates = {
      {{nu0 - 1, nv0}, {nu0, nv0 - 1}, {nu0 - 1, nv0 + 1}, {nu0 + 1, nv0 - 1}}};
  std::sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) {
    return a.first * a.second < b.first * b.second;
  });
  for (const auto& [cu, cv] : candidates)
    if (cu >= 1 && cv >= 1 && cu <= maxPerDirection && cv <= maxPerDirection &&
        cu * cv < nu0 * nv0 &&
        estimatedCellDeviation(s, 1.0 / cu, 1.0 / cv, tolerance) <= tolerance) {
      r.nu = cu;
      r.nv = cv;
      break;
    }
  if (sideSegments) fitStrips(x, s, *sideSegments, tolerance, maxPerDirection, r);
  return r;
}

}  // namespace tessera
