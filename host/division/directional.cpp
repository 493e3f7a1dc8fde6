// The directional cell bound (beyond the paper, docs/rational_division.md): a bound of the
// parametric deviation of both triangles of one grid cell that keeps the directions of the
// second partials instead of adding their norms as Filip's inequality does.
//
// For a triangle with corners x_i and a point x = Σ λ_i x_i, Taylor's formula with integral
// remainder from x towards each corner (d_i = x_i − x, Σ λ_i d_i = 0) gives the error
//   e(x) = Σ_i λ_i ∫₀¹ (1−t) d_iᵀ S''(x + t d_i) d_i dt.
// Split S'' = H + (S'' − H) with a constant H:
//   * the constant part is exactly ½ Σ_i λ_i d_iᵀ H d_i = ½ Σ_(i<j) λ_i λ_j e_ijᵀ H e_ij (the
//     weighted-variance identity; e_ij = x_i − x_j are the triangle's edges). A grid cell's
//     two triangles have the edges (1,0), (0,1) and the diagonal (1,1) in the cell's own
//     parameters, so this needs only H_uu, H_vv and H_uu + 2H_uv + H_vv, whose norms c01, c12,
//     c02 enter ½ max over the simplex of (c01 λ0λ1 + c12 λ1λ2 + c02 λ0λ2);
//   * the rest is at most Filip's bound of the remainder, (Δ_uu + 2Δ_uv + Δ_vv)/8 with
//     Δ ≥ sup over the cell of ‖S'' − H‖ per partial.
// Both sups come from the convex hull: where W = w³'s Bernstein coefficients have one strict
// sign, S''(x) = Σ_k (W_k B_k(x) / W(x)) (N_k / W_k) is a convex combination of the coefficient
// ratios N_k / W_k, so ‖S''(x) − H‖ ≤ max_k ‖N_k / W_k − H‖. H is the centre of their bounding
// box. Sub-pieces (de Casteljau) bring the ratios closer to the values, tightening Δ.
#include "division/detail/directional.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace tessera {
namespace {

struct Partials {
  glm::dvec3 uu, uv, vv;
};

// The ratios N_k / W_k of one piece in the cell's parameters (the numerators are derivatives in
// the patch's parameters, and a cell is h×k of them). False when W's coefficients are not all
// of one strict sign (then S'' need not lie in their hull).
bool appendRatios(const SecondDerivativeNumerators& num, double h, double k,
                  std::vector<Partials>& out) {
  const auto& w = num.w3.c;
  const bool positive = std::all_of(w.begin(), w.end(), [](double x) { return x > 0; });
  const bool negative = std::all_of(w.begin(), w.end(), [](double x) { return x < 0; });
  if (!positive && !negative) return false;
  for (size_t l = 0; l < w.size(); ++l)
    out.push_back({num.uu.c[l] * (h * h / w[l]), num.uv.c[l] * (h * k / w[l]),
                   num.vv.c[l] * (k * k / w[l])});
  return true;
}

bool collectRatios(const SecondDerivativeNumerators& cell, double h, double k, int depth,
                   std::vector<Partials>& out) {
  if (depth == 0) return appendRatios(cell, h, k, out);
  const int pieces = 1 << depth;
  const double size = 1.0 / pieces;
  for (int a = 0; a < pieces; ++a) {
    const double u0 = a * size;
    const SecondDerivativeNumerators strip = restrictNumerators(cell, u0, u0 + size, 0.0, 1.0);
    for (int b = 0; b < pieces; ++b) {
      const double v0 = b * size;
      const SecondDerivativeNumerators piece = restrictNumerators(strip, 0.0, 1.0, v0, v0 + size);
      if (!appendRatios(piece, h, k, out)) return false;
    }
  }
  return true;
}

glm::dvec3 boxCentre(const std::vector<Partials>& ratios, glm::dvec3 Partials::*member) {
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (const Partials& r : ratios) {
    lo = glm::min(lo, r.*member);
    hi = glm::max(hi, r.*member);
  }
  return 0.5 * (lo + hi);
}

double largestDistance(const std::vector<Partials>& ratios, glm::dvec3 Partials::*member,
                       const glm::dvec3& centre) {
  double d = 0.0;
  for (const Partials& r : ratios) d = std::max(d, glm::length(r.*member - centre));
  return d;
}

double directionalBound(const std::vector<Partials>& ratios) {
  const Partials h{boxCentre(ratios, &Partials::uu), boxCentre(ratios, &Partials::uv),
                   boxCentre(ratios, &Partials::vv)};
  const double main =
      0.5 * largestSimplexProduct(glm::length(h.uu), glm::length(h.vv),
                                  glm::length(h.uu + 2.0 * h.uv + h.vv));
  const double remainder = (largestDistance(ratios, &Partials::uu, h.uu) +
                            2.0 * largestDistance(ratios, &Partials::uv, h.uv) +
                            largestDistance(ratios, &Partials::vv, h.vv)) /
                           8.0;
  return main + remainder;
}

}  // namespace

double directionalCellBound(const SecondDerivativeNumerators& cell, double h, double k,
                            int refinement, double target) {
  double best = INFINITY;
  std::vector<Partials> ratios;
  for (int depth = 0; depth <= refinement; ++depth) {
    ratios.clear();
    if (collectRatios(cell, h, k, depth, ratios)) best = std::min(best, directionalBound(ratios));
    if (best <= target) break;
  }
  return best;
}

}  // namespace tessera
