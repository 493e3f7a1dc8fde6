// The cell-wise bound (beyond the paper): Filip's inequality holds per triangle with the sups of
// ‖S_uu‖, ‖S_uv‖, ‖S_vv‖ over that triangle, so a uniform N_u×N_v grid is good when every cell
// c passes (h²·M_uu,c + 2hk·M_uv,c + k²·M_vv,c)/8 ≤ TOL (h = 1/N_u, k = 1/N_v), with M·,c bounds
// over the cell only. The subdivided method uses one sup over the whole patch for every cell;
// here a cell far from the patch's curvature peak gets its own, smaller bound.
// The bound of a cell is the subdivided method's piece bound (numeratorRatioBounds: the exact
// Bernstein coefficients of the numerators of S'' over those of w³, division_subdivided.cpp)
// on the patch's numerator nets restricted to the cell by de Casteljau (restriction commutes
// with the products, so this is the piece bound of the cell; the values stay derivatives in the
// patch's parameters), refined 2×2 where it fails, and never above the global subdivided bound
// (both are bounds, so their minimum is). The grid returned is searched below the subdivided
// counts and every one of its cells is verified, so it never under-divides where the
// subdivided counts do not. The Directional and Direct methods run the same search, and a cell
// also passes by their own bound of its deviation (division_directional.h, division_direct.h).
#include <algorithm>
#include <cmath>

#include "division/detail/bounds.h"
#include "division/detail/direct.h"
#include "division/detail/directional.h"

namespace tessera {
namespace {

// The numerators of S'' and w³ over one region of the patch, reparametrised to [0, 1]², and
// the homogeneous net there (for the clip test).
struct RegionNets {
  SecondDerivativeNumerators num;
  HomogeneousNet h;
};

RegionNets restrictRegion(const RegionNets& r, double u0, double u1, double v0, double v1,
                          bool withHull) {
  RegionNets out;
  out.num = restrictNumerators(r.num, u0, u1, v0, v1);
  if (withHull) out.h = subNet(r.h, u0, u1, v0, v1);
  return out;
}

class CellChecker {
 public:
  CellChecker(const HomogeneousNet& net, const DivisionOptions& options,
              const SecondDerivativeBounds& global)
      : clip_(options.clip), curve_(net.m == 0), refinement_(options.cellRefinement),
        directional_(options.method == DivisionMethod::Directional && net.m > 0),
        direct_(options.method == DivisionMethod::Direct && net.m > 0),
        needNet_(clip_.enabled || direct_), directDepth_(options.directDepth),
        tolerance_(options.tolerance), limit_(8.0 * options.tolerance),
        global_{global.uu, global.uv, global.vv} {
    patch_.num = secondDerivativeNumerators(net);
    if (needNet_) patch_.h = net;
  }

  // True when every cell of the nu×nv grid passes; `largest` then holds the largest cell
  // bounds (a bound of the sups over the whole patch, visible cells only).
  bool passes(int nu, int nv, double largest[3]) {
    h_ = 1.0 / nu;
    k_ = 1.0 / nv;
    largest[0] = largest[1] = largest[2] = 0.0;
    // The cell that failed the last candidate usually fails this one too: try it first.
    const int fi = std::min(nu - 1, int(failU_ * nu)), fj = std::min(nv - 1, int(failV_ * nv));
    if (!cellPasses(cellNets(patch_, fi, nu, fj, nv), largest)) return false;
    for (int i = 0; i < nu; ++i) {
      const RegionNets strip = curve_ ? patch_ : restrictRegion(patch_, double(i) / nu,
                                                                double(i + 1) / nu, 0.0, 1.0,
                                                                needNet_);
      for (int j = 0; j < nv; ++j) {
        if (i == fi && j == fj) continue;
        const RegionNets cell = curve_ ? cellNets(patch_, i, nu, 0, 1)
                                       : restrictRegion(strip, 0.0, 1.0, double(j) / nv,
                                                        double(j + 1) / nv, needNet_);
        if (!cellPasses(cell, largest)) {
          failU_ = (i + 0.5) / nu;
          failV_ = (j + 0.5) / nv;
          return false;
        }
      }
    }
    return true;
  }

 private:
  RegionNets cellNets(const RegionNets& r, int i, int nu, int j, int nv) const {
    return restrictRegion(r, double(i) / nu, double(i + 1) / nu, double(j) / nv,
                          double(j + 1) / nv, needNet_);
  }

  double filip(const double b[3]) const { return h_ * h_ * b[0] + 2 * h_ * k_ * b[1] + k_ * k_ * b[2]; }

  bool cellPasses(const RegionNets& cell, double largest[3]) const {
    double b[3];
    // Directional and Direct: the cheap whole-cell Filip test first, then their own bound,
    // then Filip with the refined cell bounds (where w³ changes sign on the cell, say).
    const bool ownBound = directional_ || direct_;
    if (!regionBounds(cell, ownBound ? 0 : refinement_, b)) return true;  // invisible
    bool passes = filip(b) <= limit_;
    if (!passes && ownBound) {
      passes = direct_ ? cellDeviationWithin(cell.h, tolerance_, directDepth_)
                       : directionalCellBound(cell.num, h_, k_, refinement_, tolerance_) <=
                             tolerance_;
      if (!passes && !regionBounds(cell, refinement_, b)) return true;
      passes = passes || filip(b) <= limit_;
    }
    if (!passes) return false;
    for (int p = 0; p < 3; ++p) largest[p] = std::max(largest[p], b[p]);
    return true;
  }

  // Bounds over a region: its own piece bound, or where that fails Filip's test for the cell,
  // the componentwise maximum over its 2×2 sub-regions (`depth` more levels); never above the
  // global bound. False: invisible. The restricted numerators keep their values, derivatives
  // in the patch's parameters, so the piece bound takes no rescaling (hu = hv = 1).
  bool regionBounds(const RegionNets& r, int depth, double b[3]) const {
    if (clip_.enabled && outsideClip(r.h, clip_)) return false;
    const bool resolved = numeratorRatioBounds(r.num, 1.0, 1.0, b);
    if (!resolved) std::copy(global_, global_ + 3, b);
    for (int p = 0; p < 3; ++p) b[p] = std::min(b[p], global_[p]);
    if (filip(b) <= limit_ || depth == 0) return true;
    double children[3] = {0, 0, 0};
    bool anyVisible = false;
    const int splitsV = curve_ ? 1 : 2;
    for (int a = 0; a < 2; ++a)
      for (int c = 0; c < splitsV; ++c) {
        const RegionNets sub = restrictRegion(r, 0.5 * a, 0.5 * (a + 1), curve_ ? 0.0 : 0.5 * c,
                                              curve_ ? 1.0 : 0.5 * (c + 1), needNet_);
        double s[3];
        if (!regionBounds(sub, depth - 1, s)) continue;
        anyVisible = true;
        for (int p = 0; p < 3; ++p) children[p] = std::max(children[p], s[p]);
      }
    if (!anyVisible) return false;
    for (int p = 0; p < 3; ++p) b[p] = std::min(b[p], children[p]);
    return true;
  }

  RegionNets patch_;
  ClipRegion clip_;
  bool curve_;
  int refinement_;
  bool directional_;  // also pass cells by the directional bound (surfaces only)
  bool direct_;       // also pass cells by the direct deviation bound (surfaces only)
  bool needNet_;      // restrict the homogeneous net too (clip test, direct bound)
  int directDepth_;
  double tolerance_;
  double limit_;
  double global_[3];
  double h_ = 1, k_ = 1;
  double failU_ = 0.5, failV_ = 0.5;
};

}  // namespace

Divisions cellwiseDivisions(const HomogeneousNet& net, const DivisionOptions& options,
                            const Divisions& subdivided) {
  if (subdivided.status != DivisionStatus::Ok) return subdivided;
  CellChecker checker(net, options, subdivided.bounds);
  Divisions best = subdivided;
  double largest[3];
  // The subdivided grid passes (every cell bound is at most the global one); verify anyway so
  // that `best.bounds` holds the cell bounds actually used.
  if (!checker.passes(best.nu, best.nv, largest)) return subdivided;
  auto keep = [&](int nu, int nv) {
    best.nu = nu;
    best.nv = nv;
    best.bounds.uu = largest[0];
    best.bounds.uv = largest[1];
    best.bounds.vv = largest[2];
  };
  keep(best.nu, best.nv);
  // A candidate that passes becomes the answer when it has fewer faces.
  auto check = [&](int nu, int nv) {
    if (!checker.passes(nu, nv, largest)) return false;
    if (static_cast<long long>(nu) * nv < best.divisionNumber()) keep(nu, nv);
    return true;
  };
  // 1. A common scale of both counts, binary search on the larger one (deviation shrinks as
  // the grid grows; where it does not, a candidate fails and costs only optimality).
  const int nu0 = best.nu, nv0 = best.nv, large = std::max(nu0, nv0);
  auto scaled = [&](int s, int n0) {
    return std::max(1, int(std::ceil(double(s) * n0 / large - 1e-9)));
  };
  for (int lo = 1, hi = large - 1; lo <= hi;) {
    const int mid = (lo + hi) / 2;
    if (check(scaled(mid, nu0), scaled(mid, nv0)))
      hi = mid - 1;
    else
      lo = mid + 1;
  }
  // 2. Each direction on its own, the other held, until neither shrinks.
  for (int round = 0; round < 3; ++round) {
    const long long before = best.divisionNumber();
    for (int direction = 0; direction < (net.m == 0 ? 1 : 2); ++direction)
      for (int lo = 1, hi = (direction == 0 ? best.nu : best.nv) - 1; lo <= hi;) {
        const int mid = (lo + hi) / 2;
        if (direction == 0 ? check(mid, best.nv) : check(best.nu, mid))
          hi = mid - 1;
        else
          lo = mid + 1;
      }
    if (best.divisionNumber() == before) break;
  }
  best.realU = best.nu;
  best.realV = best.nv;
  return best;
}

}  // namespace tessera
