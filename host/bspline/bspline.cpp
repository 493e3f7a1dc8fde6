#include "bspline/bspline.h"

#include <stdexcept>
#include <string>

#include "bspline/knots.h"

namespace tessera {

namespace {

// O(1) shape checks for the evaluators; full knot validation is validateCurve's job.
void checkShape(int degree, size_t knotCount, size_t controlCount, const char* what) {
  if (degree < 1 || degree > kMaxDegree || controlCount < static_cast<size_t>(degree) + 1 ||
      knotCount != controlCount + static_cast<size_t>(degree) + 1) {
    throw std::invalid_argument(std::string(what) + ": degree " + std::to_string(degree) +
                                " with " + std::to_string(controlCount) + " control points and " +
                                std::to_string(knotCount) + " knots is not a B-spline");
  }
}

void checkSurfaceShape(const BSplineSurface& s) {
  if (s.countU < 0 || s.countV < 0 ||
      s.cp.size() != static_cast<size_t>(s.countU) * static_cast<size_t>(s.countV)) {
    throw std::invalid_argument("B-spline surface: " + std::to_string(s.cp.size()) +
                                " control points for a " + std::to_string(s.countU) + " x " +
                                std::to_string(s.countV) + " net");
  }
  checkShape(s.degreeU, s.knotsU.size(), static_cast<size_t>(s.countU), "B-spline surface (u)");
  checkShape(s.degreeV, s.knotsV.size(), static_cast<size_t>(s.countV), "B-spline surface (v)");
}

double ratioOrZero(double num, double den) { return den == 0.0 ? 0.0 : num / den; }

// The last non-empty knot interval, closed on the right by basisFunction's convention.
size_t lastNonEmptyInterval(const std::vector<double>& x) {
  size_t i = x.size() - 1;
  while (i > 0 && x[i - 1] == x.back()) --i;
  return i == 0 ? 0 : i - 1;
}

// tri[d][r] = N_{span-d+r, d}(t) for every degree d ≤ p: the derivative formula needs the
// lower degrees, and the final row is the basis itself.
using BasisTriangle = std::array<BasisRow, kMaxDegree + 1>;
BasisTriangle basisTriangle(int span, int degree, const std::vector<double>& x, double t) {
  const int n = static_cast<int>(x.size()) - degree - 1;
  if (degree < 0 || degree > kMaxDegree || span < degree || span >= n) {
    throw std::invalid_argument("basis: span " + std::to_string(span) + " is not in [p, n-1] = [" +
                                std::to_string(degree) + ", " + std::to_string(n - 1) +
                                "] for degree " + std::to_string(degree));
  }
  BasisTriangle tri{};
  std::array<double, kMaxDegree + 1> left{}, right{};
  tri[0][0] = 1.0;
  for (int d = 1; d <= degree; ++d) {
    left[d] = t - x[static_cast<size_t>(span + 1 - d)];
    right[d] = x[static_cast<size_t>(span + d)] - t;
    double carried = 0.0;
    for (int r = 0; r < d; ++r) {
      // right[r+1] + left[d-r] = x_{span+r+1} − x_{span+r+1-d} ≥ x_{span+1} − x_span > 0.
      const double share = tri[d - 1][r] / (right[r + 1] + left[d - r]);
      tri[d][r] = carried + right[r + 1] * share;
      carried = left[d - r] * share;
    }
    tri[d][d] = carried;
  }
  return tri;
}

}  // namespace

void validateCurve(const BSplineCurve& curve) {
  validateKnots(curve.degree, static_cast<int>(curve.cp.size()), curve.knots, "B-spline curve");
}

void validateSurface(const BSplineSurface& surface) {
  checkSurfaceShape(surface);
  validateKnots(surface.degreeU, surface.countU, surface.knotsU, "B-spline surface knotsU");
  validateKnots(surface.degreeV, surface.countV, surface.knotsV, "B-spline surface knotsV");
}

double basisFunction(int i, int degree, const std::vector<double>& x, double t) {
  if (degree < 0 || i < 0 || static_cast<size_t>(i + degree + 1) >= x.size()) {
    throw std::invalid_argument("basisFunction: N_{" + std::to_string(i) + "," +
                                std::to_string(degree) + "} needs knots up to index " +
                                std::to_string(i + degree + 1) + ", have " +
                                std::to_string(x.size()));
  }
  const size_t k = static_cast<size_t>(i);
  if (degree == 0) {
    if (x[k] <= t && t < x[k + 1]) return 1.0;
    return t == x.back() && k == lastNonEmptyInterval(x) ? 1.0 : 0.0;
  }
  const size_t p = static_cast<size_t>(degree);
  return ratioOrZero(t - x[k], x[k + p] - x[k]) * basisFunction(i, degree - 1, x, t) +
         ratioOrZero(x[k + p + 1] - t, x[k + p + 1] - x[k + 1]) *
             basisFunction(i + 1, degree - 1, x, t);
}

double basisFunctionDerivative(int i, int degree, const std::vector<double>& x, double t,
                               int order) {
  if (order < 0) throw std::invalid_argument("basisFunctionDerivative: negative order");
  if (order == 0) return basisFunction(i, degree, x, t);
  if (degree == 0) return 0.0;
  const size_t k = static_cast<size_t>(i);
  const size_t p = static_cast<size_t>(degree);
  return ratioOrZero(degree, x[k + p] - x[k]) *
             basisFunctionDerivative(i, degree - 1, x, t, order - 1) -
         ratioOrZero(degree, x[k + p + 1] - x[k + 1]) *
             basisFunctionDerivative(i + 1, degree - 1, x, t, order - 1);
}

BasisRow basisFunctions(int span, int degree, const std::vector<double>& knots, double t) {
  return basisTriangle(span, degree, knots, t)[static_cast<size_t>(degree)];
}

BasisTable basisDerivatives(int span, int degree, const std::vector<double>& x, double t,
                            int order) {
  const BasisTriangle tri = basisTriangle(span, degree, x, t);
  BasisTable table{};
  table[0] = tri[static_cast<size_t>(degree)];
  const int top = order < degree ? order : degree;
  // D^k N_{i,p} = p!/(p−k)! Σ_j a_{k,j} N_{i+j,p−k}, with
  // a_{k,j} = (a_{k−1,j} − a_{k−1,j−1}) / (x_{i+j+p−k+1} − x_{i+j}) (Piegl & Tiller,
  // The NURBS Book eq. 2.9–2.10). A zero denominator means N_{i+j,p−k} ≡ 0, and so are all
  // its derivatives: a_{k,j} = 0 drops it exactly.
  for (int r = 0; r <= degree; ++r) {
    const int i = span - degree + r;
    std::array<double, kMaxDegree + 2> a{}, next{};
    a[0] = 1.0;
    double falling = 1.0;  // p (p−1) … (p−k+1)
    for (int k = 1; k <= top; ++k) {
      falling *= degree - k + 1;
      const int low = degree - k;  // degree of the basis the k-th derivative is written in
      double sum = 0.0;
      for (int j = 0; j <= k; ++j) {
        const double diff = (j < k ? a[static_cast<size_t>(j)] : 0.0) -
                            (j > 0 ? a[static_cast<size_t>(j - 1)] : 0.0);
        const double den = x[static_cast<size_t>(i + j + low + 1)] - x[static_cast<size_t>(i + j)];
        next[static_cast<size_t>(j)] = ratioOrZero(diff, den);
        // N_{i+j, low} is nonzero on span only for i+j ∈ [span−low, span].
        const int slot = i + j - (span - low);
        if (slot >= 0 && slot <= low) {
          sum += next[static_cast<size_t>(j)] *
                 tri[static_cast<size_t>(low)][static_cast<size_t>(slot)];
        }
      }
      table[static_cast<size_t>(k)][static_cast<size_t>(r)] = falling * sum;
      a = next;
    }
  }
  return table;
}

glm::dvec3 curvePoint(const BSplineCurve& c, double t) {
  checkShape(c.degree, c.knots.size(), c.cp.size(), "B-spline curve");
  const int span = findSpan(c.degree, c.knots, t);
  const BasisRow n = basisFunctions(span, c.degree, c.knots, t);
  glm::dvec3 p(0.0);
  for (int r = 0; r <= c.degree; ++r) {
    p += n[static_cast<size_t>(r)] * c.cp[static_cast<size_t>(span - c.degree + r)];
  }
  return p;
}

BSplineCurveDerivatives curveDerivatives(const BSplineCurve& c, double t) {
  checkShape(c.degree, c.knots.size(), c.cp.size(), "B-spline curve");
  const int span = findSpan(c.degree, c.knots, t);
  const BasisTable n = basisDerivatives(span, c.degree, c.knots, t, 2);
  BSplineCurveDerivatives d{glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0)};
  for (int r = 0; r <= c.degree; ++r) {
    const glm::dvec3& q = c.cp[static_cast<size_t>(span - c.degree + r)];
    d.p += n[0][static_cast<size_t>(r)] * q;
    d.d1 += n[1][static_cast<size_t>(r)] * q;
    d.d2 += n[2][static_cast<size_t>(r)] * q;
  }
  return d;
}

glm::dvec3 surfacePoint(const BSplineSurface& s, double u, double v) {
  checkSurfaceShape(s);
  const int su = findSpan(s.degreeU, s.knotsU, u);
  const int sv = findSpan(s.degreeV, s.knotsV, v);
  const BasisRow nu = basisFunctions(su, s.degreeU, s.knotsU, u);
  const BasisRow nv = basisFunctions(sv, s.degreeV, s.knotsV, v);
  glm::dvec3 p(0.0);
  for (int r = 0; r <= s.degreeU; ++r) {
    glm::dvec3 row(0.0);
    for (int c = 0; c <= s.degreeV; ++c) {
      row += nv[static_cast<size_t>(c)] * s.at(su - s.degreeU + r, sv - s.degreeV + c);
    }
    p += nu[static_cast<size_t>(r)] * row;
  }
  return p;
}

SurfaceDerivatives surfaceDerivatives(const BSplineSurface& s, double u, double v) {
  checkSurfaceShape(s);
  const int su = findSpan(s.degreeU, s.knotsU, u);
  const int sv = findSpan(s.degreeV, s.knotsV, v);
  const BasisTable nu = basisDerivatives(su, s.degreeU, s.knotsU, u, 3);
  const BasisTable nv = basisDerivatives(sv, s.degreeV, s.knotsV, v, 3);
  // mixed[a][b] = ∂^{a+b} S / ∂u^a ∂v^b, a + b ≤ 3; each row of the net is first
  // contracted along v, then the rows along u.
  std::array<std::array<glm::dvec3, 4>, 4> mixed;
  for (auto& row : mixed) row.fill(glm::dvec3(0.0));
  for (int r = 0; r <= s.degreeU; ++r) {
    std::array<glm::dvec3, 4> alongV;
    alongV.fill(glm::dvec3(0.0));
    for (int c = 0; c <= s.degreeV; ++c) {
      const glm::dvec3& q = s.at(su - s.degreeU + r, sv - s.degreeV + c);
      for (size_t b = 0; b < 4; ++b) alongV[b] += nv[b][static_cast<size_t>(c)] * q;
    }
    for (size_t a = 0; a < 4; ++a) {
      for (size_t b = 0; a + b < 4; ++b) mixed[a][b] += nu[a][static_cast<size_t>(r)] * alongV[b];
    }
  }
  return surfaceDerivativesFrom<3>(mixed);
}

}  // namespace tessera
