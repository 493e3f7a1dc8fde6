#include "bspline/to_bezier.h"

#include <stdexcept>
#include <string>

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

// The Oslo matrix (osloMatrix, oslo.h) as its rows' nonzero windows: row r holds values
// [r·(p + 1), (r + 1)·(p + 1)) for columns first[r] … first[r] + p, the entries osloMatrix
// writes into its dense matrix of zeros. A piece conversion spent more on that matrix's zeros
// (allocating, clearing, scanning m × n entries per direction) than on its p + 1 per row.
struct InsertionRows {
  int rows = 0, cols = 0, degree = 0;
  std::vector<int> first;
  std::vector<double> values;
};

// Validated as osloMatrix validates (validateOsloKnots, the same messages).
InsertionRows insertionRows(int degree, const std::vector<double>& x, const std::vector<double>& y) {
  const int p = degree;
  const int n = static_cast<int>(x.size()) - p - 1;
  const int m = static_cast<int>(y.size()) - p - 1;
  validateOsloKnots(p, x, y);
  InsertionRows a{m, n, p, std::vector<int>(size_t(m)), std::vector<double>(size_t(m) * size_t(p + 1))};
  for (int j = 0; j < m; ++j) a.first[size_t(j)] = osloRow(p, x, y, j, a.values.data() + size_t(j) * size_t(p + 1));
  return a;
}

// applyToNet (oslo.h) of the rows' matrix: each output point sums w·Q over the row's nonzero
// w in ascending column order from 0, as applyToNet sums over the dense row: the same bits.
std::vector<glm::dvec3> applyRowsToNet(const InsertionRows& a, const std::vector<glm::dvec3>& cp,
                                       int countU, int countV, ParamDirection direction) {
  const bool alongU = direction == ParamDirection::U;
  if (cp.size() != size_t(countU) * size_t(countV) || a.cols != (alongU ? countU : countV))
    throw std::invalid_argument("applyToNet: a " + std::to_string(a.rows) + " x " + std::to_string(a.cols) +
                                " matrix does not fit a " + std::to_string(countU) + " x " +
                                std::to_string(countV) + " net along " + (alongU ? "u" : "v"));
  const int outU = alongU ? a.rows : countU;
  const int outV = alongU ? countV : a.rows;
  std::vector<glm::dvec3> out(size_t(outU) * size_t(outV), glm::dvec3(0.0));
  for (int r = 0; r < a.rows; ++r) {
    const double* row = a.values.data() + size_t(r) * size_t(a.degree + 1);
    for (int t = 0; t <= a.degree; ++t) {
      const double w = row[t];
      if (w == 0.0) continue;
      const int c = a.first[size_t(r)] + t;
      if (alongU) {
        const glm::dvec3* in = cp.data() + size_t(c) * size_t(countV);
        glm::dvec3* at = out.data() + size_t(r) * size_t(outV);
        for (int j = 0; j < countV; ++j) at[j] += w * in[j];
      } else {
        for (int i = 0; i < countU; ++i)
          out[size_t(i) * size_t(outV) + size_t(r)] += w * cp[size_t(i) * size_t(countV) + size_t(c)];
      }
    }
  }
  return out;
}

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
  const InsertionRows alongU = insertionRows(p, surface.knotsU, knotsU);
  const InsertionRows alongV = insertionRows(q, surface.knotsV, knotsV);
  const int countU = alongU.rows, countV = alongV.rows;
  std::vector<std::vector<BezierPatchPiece>> out;
  for (const std::vector<glm::dvec3>* net : nets) {
    const std::vector<glm::dvec3> refined = applyRowsToNet(
        alongV, applyRowsToNet(alongU, *net, surface.countU, surface.countV, ParamDirection::U),
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
