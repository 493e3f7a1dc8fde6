// The subdivided bound (beyond the paper): split the patch by de Casteljau into pieces, bound
// sup‖S''‖ on each piece by the exact Bernstein coefficients of its numerator over those of w³,
// and refine only the pieces whose bound is still well above what sampling finds there.
// Pieces where w's coefficients are not all of one sign (a vanished weight at the piece, the
// eye plane crossing it) are refined until they are, or found outside the visible region.
#include <algorithm>
#include <cmath>
#include <vector>

#include "division/detail/bounds.h"

namespace tessera {
namespace {

// x.P·y.w − x.w·y.P as a polynomial (bidegree of x plus bidegree of y).
VectorNet wedge(const HomogeneousNet& x, const HomogeneousNet& y) {
  const VectorNet a = product(weightsOf(y), numeratorsOf(x));
  const VectorNet b = product(weightsOf(x), numeratorsOf(y));
  if (a.n == b.n && a.m == b.m) return combine(a, 1.0, b, -1.0);
  const int n = std::max(a.n, b.n), m = std::max(a.m, b.m);
  return combine(elevate(a, n, m), 1.0, elevate(b, n, m), -1.0);
}

VectorNet sumAt(const VectorNet& a, double sa, const VectorNet& b, double sb, int n, int m) {
  return combine(elevate(a, n, m), sa, elevate(b, n, m), sb);
}

struct Piece {
  double u0 = 0, u1 = 1, v0 = 0, v1 = 1;
  int depth = 0;
  bool visible = true;
  bool resolved = true;
  double b[3] = {0, 0, 0};  // bounds of ‖S_uu‖, ‖S_uv‖, ‖S_vv‖ in the patch's own parameters
};

void evaluatePiece(const HomogeneousNet& net, const DivisionOptions& options, Piece& piece) {
  const HomogeneousNet sub = subNet(net, piece.u0, piece.u1, piece.v0, piece.v1);
  piece.visible = !outsideClip(sub, options.clip);
  if (!piece.visible) return;
  piece.resolved = numeratorRatioBounds(secondDerivativeNumerators(sub), piece.u1 - piece.u0,
                                        piece.v1 - piece.v0, piece.b);
}

// The largest ‖S''‖ actually found at a few points of the piece: what refinement aims for.
void sampleLower(const HomogeneousNet& net, const Piece& piece, double lower[3]) {
  for (double fu : {0.5, 0.0, 1.0})
    for (double fv : {0.5, 0.0, 1.0}) {
      const double u = piece.u0 + fu * (piece.u1 - piece.u0);
      const double v = piece.v0 + fv * (piece.v1 - piece.v0);
      const ProjectedSecondDerivatives d = projectedDerivatives(net, u, v);
      if (!(d.w != 0.0) || !std::isfinite(d.w)) continue;
      lower[0] = std::max(lower[0], glm::length(d.puu));
      lower[1] = std::max(lower[1], glm::length(d.puv));
      lower[2] = std::max(lower[2], glm::length(d.pvv));
    }
}

std::vector<Piece> split(const Piece& p, bool curve) {
  const double um = 0.5 * (p.u0 + p.u1), vm = 0.5 * (p.v0 + p.v1);
  Piece a = p;
  a.depth = p.depth + 1;
  if (curve) {
    Piece b = a;
    a.u1 = um;
    b.u0 = um;
    return {a, b};
  }
  std::vector<Piece> out(4, a);
  out[0].u1 = um, out[0].v1 = vm;
  out[1].u0 = um, out[1].v1 = vm;
  out[2].u1 = um, out[2].v0 = vm;
  out[3].u0 = um, out[3].v0 = vm;
  return out;
}

}  // namespace

bool outsideClip(const HomogeneousNet& net, const ClipRegion& clip) {
  if (!clip.enabled) return false;
  // All control points beyond one plane of the region: the convex hull is, so the piece is.
  auto allOutside = [&](auto outside) {
    return std::all_of(net.c.begin(), net.c.end(), outside);
  };
  return allOutside([&](const glm::dvec4& h) { return h.w <= clip.nearW; }) ||
         allOutside([&](const glm::dvec4& h) { return h.x < 0.0; }) ||
         allOutside([&](const glm::dvec4& h) { return h.y < 0.0; }) ||
         allOutside([&](const glm::dvec4& h) { return h.x > h.w * clip.width; }) ||
         allOutside([&](const glm::dvec4& h) { return h.y > h.w * clip.height; });
}

bool numeratorRatioBounds(const SecondDerivativeNumerators& num, double hu, double hv,
                          double bounds[3]) {
  // W's coefficients of one strict sign (they are when w's are) make ‖N/W‖ ≤ max_k ‖N_k‖/|W_k|.
  const bool positive = std::all_of(num.w3.c.begin(), num.w3.c.end(), [](double w) { return w > 0; });
  const bool negative = std::all_of(num.w3.c.begin(), num.w3.c.end(), [](double w) { return w < 0; });
  if (!positive && !negative) return false;
  double best[3] = {0, 0, 0};
  const VectorNet* nets[3] = {&num.uu, &num.uv, &num.vv};
  for (size_t k = 0; k < num.w3.c.size(); ++k)
    for (int p = 0; p < 3; ++p)
      if (!nets[p]->c.empty())
        best[p] = std::max(best[p], glm::length(nets[p]->c[k]) / std::abs(num.w3.c[k]));
  bounds[0] = best[0] / (hu * hu);
  bounds[1] = best[1] / (hu * hv);
  bounds[2] = best[2] / (hv * hv);
  return true;
}

SecondDerivativeNumerators restrictNumerators(const SecondDerivativeNumerators& num, double u0,
                                              double u1, double v0, double v1) {
  // (A curve's nets have degree 0 in v, which restriction leaves as it is.)
  auto cut = [&](const auto& net) { return net.c.empty() ? net : subNet(net, u0, u1, v0, v1); };
  return {cut(num.uu), cut(num.uv), cut(num.vv), cut(num.w3)};
}

SecondDerivativeNumerators secondDerivativeNumerators(const HomogeneousNet& h) {
  const int n = h.n, m = h.m, N = 3 * n, M = 3 * m;
  const ScalarNet w = weightsOf(h);
  const HomogeneousNet hu = hodographU(h), hv = hodographV(h);
  SecondDerivativeNumerators r;
  // N_uu = w (P_uu w − w_uu P) − 2 w_u (P_u w − w_u P)
  r.uu = sumAt(product(w, wedge(hodographU(hu), h)), 1.0, product(weightsOf(hu), wedge(hu, h)),
               -2.0, N, M);
  if (m > 0) {
    r.vv = sumAt(product(w, wedge(hodographV(hv), h)), 1.0,
                 product(weightsOf(hv), wedge(hv, h)), -2.0, N, M);
    // N_uv = w (P_uv w − w_uv P + P_u w_v − w_u P_v) − 2 w_v (P_u w − w_u P)
    const VectorNet a = wedge(hodographV(hu), h), b = wedge(hu, hv);
    const int an = std::max(a.n, b.n), am = std::max(a.m, b.m);
    r.uv = sumAt(product(w, sumAt(a, 1.0, b, 1.0, an, am)), 1.0,
                 product(weightsOf(hv), wedge(hu, h)), -2.0, N, M);
  }
  r.w3 = product(w, product(w, w));
  return r;
}

SecondDerivativeBounds subdividedBounds(const HomogeneousNet& net, const DivisionOptions& options) {
  const bool curve = net.m == 0;
  std::vector<Piece> pieces;
  double lower[3] = {0, 0, 0};
  // Start from a 2×2 split: a vanished weight never leaves the root resolved anyway.
  for (const Piece& p : split(Piece{}, curve)) {
    pieces.push_back(p);
    evaluatePiece(net, options, pieces.back());
    sampleLower(net, pieces.back(), lower);
  }
  const double T = 8.0 * options.tolerance;
  for (;;) {
    double g[3] = {0, 0, 0};
    bool allResolved = true;
    for (const Piece& p : pieces) {
      if (!p.visible) continue;
      allResolved = allResolved && p.resolved;
      for (int k = 0; k < 3; ++k) g[k] = std::max(g[k], p.b[k]);
    }
    // A partial matters when its term takes a visible share of Filip's inequality at the
    // counts the current bounds give; refining a negligible one would waste the budget.
    bool relevant[3] = {true, !curve, !curve};
    if (allResolved) {
      const Divisions d = divisionsFromBounds({g[0], g[1], g[2]}, options.tolerance,
                                              1 << 30);
      const double share[3] = {g[0] / (d.realU * d.realU), 2 * g[1] / (d.realU * d.realV),
                               g[2] / (d.realV * d.realV)};
      for (int k = 0; k < 3; ++k) relevant[k] = relevant[k] && share[k] > 0.02 * T;
    }
    std::vector<size_t> refine;
    for (size_t i = 0; i < pieces.size(); ++i) {
      const Piece& p = pieces[i];
      if (!p.visible || p.depth >= options.maxDepth) continue;
      bool loose = !p.resolved;
      for (int k = 0; k < 3 && !loose; ++k)
        loose = relevant[k] && p.b[k] > (1.0 + options.refineSlack) * lower[k];
      if (loose) refine.push_back(i);
    }
    const size_t children = curve ? 2 : 4;
    const size_t room = pieces.size() >= static_cast<size_t>(options.maxPieces)
                            ? 0
                            : (options.maxPieces - pieces.size()) / (children - 1);
    if (refine.empty() || room == 0) break;
    if (refine.size() > room) {
      // Out of budget: the unresolved pieces first, then the loosest.
      auto looseness = [&](size_t i) {
        const Piece& p = pieces[i];
        if (!p.resolved) return double(INFINITY);
        double worst = 0.0;
        for (int k = 0; k < 3; ++k)
          if (relevant[k] && lower[k] > 0.0) worst = std::max(worst, p.b[k] / lower[k]);
        return worst;
      };
      std::stable_sort(refine.begin(), refine.end(),
                       [&](size_t x, size_t y) { return looseness(x) > looseness(y); });
      refine.resize(room);
      std::sort(refine.begin(), refine.end());
    }
    std::vector<Piece> next;
    next.reserve(pieces.size() + refine.size() * (children - 1));
    size_t r = 0;
    for (size_t i = 0; i < pieces.size(); ++i) {
      if (r < refine.size() && refine[r] == i) {
        ++r;
        for (Piece c : split(pieces[i], curve)) {
          evaluatePiece(net, options, c);
          sampleLower(net, c, lower);
          next.push_back(c);
        }
      } else {
        next.push_back(pieces[i]);
      }
    }
    pieces.swap(next);
  }

  SecondDerivativeBounds bounds;
  bounds.visible = false;
  bounds.pieces = static_cast<int>(pieces.size());
  for (const Piece& p : pieces) {
    if (!p.visible) continue;
    bounds.visible = true;
    if (!p.resolved) bounds.bounded = false;
    bounds.uu = std::max(bounds.uu, p.b[0]);
    bounds.uv = std::max(bounds.uv, p.b[1]);
    bounds.vv = std::max(bounds.vv, p.b[2]);
  }
  if (!bounds.bounded) bounds.uu = bounds.uv = bounds.vv = INFINITY;
  return bounds;
}

}  // namespace tessera
