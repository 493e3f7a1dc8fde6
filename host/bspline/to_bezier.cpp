#include "bspline/to_bezier.h"

#include "bspline/knots.h"
#include "bspline/oslo.h"
#include "common/memory_budget.h"

namespace tessera {

namespace {

// Non-empty spans μ (y_μ < y_{μ+1}) of a knot vector already at Bézier multiplicity. The
// domain of y is [y_p, y_m] = [x_p, x_n]: the inserted copies sit inside the domain.
std::vector<int> nonEmptySpans(int degree, const std::vector<double>& y) {
  const int m = static_cast<int>(y.size()) - degree - 1;
  std::vector<int> spans;
  for (int mu = degree; mu < m; ++mu) {
    if (y[static_cast<size_t>(mu)] < y[static_cast<size_t>(mu + 1)]) spans.push_back(mu);
  }
  return spans;
}

}  // namespace

std::vector<double> bezierKnots(int degree, const std::vector<double>& knots) {
  const int n = static_cast<int>(knots.size()) - degree - 1;
  validateKnots(degree, n, knots, "bezierKnots");
  const double lo = knots[static_cast<size_t>(degree)];
  const double hi = knots[static_cast<size_t>(n)];
  std::vector<double> inserted;
  for (size_t k = 0; k < knots.size(); ++k) {
    const double v = knots[k];
    if (v < lo || v > hi || (k > 0 && knots[k - 1] == v)) continue;
    for (int c = knotMultiplicity(knots, v); c < degree; ++c) inserted.push_back(v);
  }
  return mergeKnots(knots, inserted);
}

std::vector<BezierCurvePiece> bezierPieces(const BSplineCurve& curve) {
  const int p = curve.degree;
  const BSplineCurve refined = refineCurve(curve, bezierKnots(p, curve.knots));
  std::vector<BezierCurvePiece> pieces;
  for (int mu : nonEmptySpans(p, refined.knots)) {
    BezierCurvePiece piece;
    piece.curve.degree = p;
    piece.curve.cp.assign(refined.cp.begin() + (mu - p), refined.cp.begin() + (mu + 1));
    piece.t0 = refined.knots[static_cast<size_t>(mu)];
    piece.t1 = refined.knots[static_cast<size_t>(mu + 1)];
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

namespace {

// The pieces of `surface`'s knots and degrees for each net in `nets` (each countU × countV,
// `surface.cp` among them or not): every knot raised to multiplicity p, then a piece per pair
// of non-empty spans. The insertion's two matrices are built once for all the nets; each net
// goes through them as refineSurface along u, then along v, would take it.
std::vector<std::vector<BezierPatchPiece>> patchesOfNets(
    const BSplineSurface& surface, const std::vector<const std::vector<glm::dvec3>*>& nets) {
  const int p = surface.degreeU;
  const int q = surface.degreeV;
  validateSurface(surface);
  const std::vector<double> knotsU = bezierKnots(p, surface.knotsU);
  const std::vector<double> knotsV = bezierKnots(q, surface.knotsV);
  const std::vector<int> spansU = nonEmptySpans(p, knotsU);
  const std::vector<int> spansV = nonEmptySpans(q, knotsV);
  // Before refining: the net refined along u, then along both, and the pieces (held twice at
  // the peak: here and as the tessellator's patch list), from the counts the knots give.
  const uint64_t refinedU = knotsU.size() - size_t(p) - 1, refinedV = knotsV.size() - size_t(q) - 1;
  const uint64_t pieces = saturatingMultiply(spansU.size(), spansV.size());
  const uint64_t pieceBytes = sizeof(BezierPatchPiece) + 16 +  // 16: the allocator's header
                              uint64_t(p + 1) * uint64_t(q + 1) * sizeof(glm::dvec3);
  uint64_t bytes = saturatingMultiply(saturatingMultiply(refinedU, uint64_t(surface.countV)) +
                                          saturatingMultiply(refinedU, refinedV),
                                      sizeof(glm::dvec3));
  bytes = saturatingAdd(bytes, saturatingMultiply(2 * pieceBytes, pieces));
  // The message only when it is needed: a CAD model converts thousands of small surfaces.
  if (bytes > memoryBudget())
    requireWithinMemoryBudget(bytes, "the degree " + std::to_string(p) + "×" + std::to_string(q) +
                                         " B-spline of " + std::to_string(surface.countU) + "×" +
                                         std::to_string(surface.countV) + " control points as " +
                                         std::to_string(pieces) + " Bézier pieces");
  const Eigen::MatrixXd alongU = osloMatrix(p, surface.knotsU, knotsU);
  const Eigen::MatrixXd alongV = osloMatrix(q, surface.knotsV, knotsV);
  const int countU = int(alongU.rows()), countV = int(alongV.rows());
  std::vector<std::vector<BezierPatchPiece>> out;
  for (const std::vector<glm::dvec3>* net : nets) {
    const std::vector<glm::dvec3> refined = applyToNet(
        alongV, applyToNet(alongU, *net, surface.countU, surface.countV, ParamDirection::U),
        countU, surface.countV, ParamDirection::V);
    const auto at = [&](int i, int j) { return refined[size_t(i) * size_t(countV) + size_t(j)]; };
    std::vector<BezierPatchPiece> patches;
    patches.reserve(spansU.size() * spansV.size());
    for (int mu : spansU) {
      for (int nu : spansV) {
        BezierPatchPiece piece;
        piece.patch.degreeU = p;
        piece.patch.degreeV = q;
        piece.patch.cp.resize(static_cast<size_t>((p + 1) * (q + 1)));
        for (int i = 0; i <= p; ++i) {
          for (int j = 0; j <= q; ++j) piece.patch.at(i, j) = at(mu - p + i, nu - q + j);
        }
        piece.u0 = knotsU[static_cast<size_t>(mu)];
        piece.u1 = knotsU[static_cast<size_t>(mu + 1)];
        piece.v0 = knotsV[static_cast<size_t>(nu)];
        piece.v1 = knotsV[static_cast<size_t>(nu + 1)];
        patches.push_back(std::move(piece));
      }
    }
    out.push_back(std::move(patches));
  }
  return out;
}

}  // namespace

std::vector<BezierPatchPiece> bezierPatches(const BSplineSurface& surface) {
  return std::move(patchesOfNets(surface, {&surface.cp}).front());
}

std::pair<std::vector<BezierPatchPiece>, std::vector<BezierPatchPiece>> bezierPatchPair(
    const BSplineSurface& surface, const std::vector<glm::dvec3>& companion) {
  std::vector<std::vector<BezierPatchPiece>> both = patchesOfNets(surface, {&surface.cp, &companion});
  return {std::move(both[0]), std::move(both[1])};
}

}  // namespace tessera
