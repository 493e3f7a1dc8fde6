// Division counts: input checks, the corrected A_ijk, the B1..B8 class bound (AbiEzzi,
// PaperSplit, Split) and the closed-form counts. Derivation: docs/rational_division.md.
#include "division/count.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "division/detail/bounds.h"

namespace tessera {
namespace {

[[noreturn]] void fail(const std::string& where, const std::string& reason) {
  throw std::invalid_argument(where + ": " + reason);
}

void checkNet(const HomogeneousNet& net, DivisionMethod method, const std::string& where) {
  bool allZero = true, anyZero = false, anyNegative = false, anyPositive = false;
  for (size_t k = 0; k < net.c.size(); ++k) {
    const glm::dvec4& h = net.c[k];
    for (int c = 0; c < 4; ++c)
      if (!std::isfinite(h[c]))
        fail(where, "control point " + std::to_string(k) + " has a non-finite coordinate");
    allZero = allZero && h.w == 0.0;
    anyZero = anyZero || h.w == 0.0;
    anyNegative = anyNegative || h.w < 0.0;
    anyPositive = anyPositive || h.w > 0.0;
  }
  if (allZero) fail(where, "every weight is zero: the curve or patch lies at infinity");
  if (method == DivisionMethod::AbiEzzi && (anyZero || (anyNegative && anyPositive)))
    fail(where,
         "the Abi-Ezzi bound needs every weight non-zero and of one sign (use the split "
         "method for zero or mixed weights)");
  if (method == DivisionMethod::PaperSplit && anyNegative)
    fail(where, "the paper's B1..B8 assumes weights ≥ 0 (use the split method for negative ones)");
}

HomogeneousNet checkedNet(const RationalBezierCurve& curve, DivisionMethod method) {
  const std::string where = "division count (curve)";
  if (curve.degree < 1 || curve.degree > kMaxDegree)
    fail(where, "degree " + std::to_string(curve.degree) + " is outside 1.." +
                    std::to_string(kMaxDegree));
  if (curve.cpw.size() != static_cast<size_t>(curve.degree + 1))
    fail(where, "a degree-" + std::to_string(curve.degree) + " curve needs " +
                    std::to_string(curve.degree + 1) + " control points, got " +
                    std::to_string(curve.cpw.size()));
  HomogeneousNet net = toNet(curve);
  checkNet(net, method, where);
  return net;
}

HomogeneousNet checkedNet(const RationalBezierPatch& patch, DivisionMethod method) {
  const std::string where = "division count (patch)";
  if (patch.degreeU < 1 || patch.degreeU > kMaxDegree || patch.degreeV < 1 ||
      patch.degreeV > kMaxDegree)
    fail(where, "degree (" + std::to_string(patch.degreeU) + ", " +
                    std::to_string(patch.degreeV) + ") is outside 1.." +
                    std::to_string(kMaxDegree));
  const size_t expected = static_cast<size_t>((patch.degreeU + 1) * (patch.degreeV + 1));
  if (patch.cpw.size() != expected)
    fail(where, "needs " + std::to_string(expected) + " control points, got " +
                    std::to_string(patch.cpw.size()));
  HomogeneousNet net = toNet(patch);
  checkNet(net, method, where);
  return net;
}

// X.P·Y.w − X.w·Y.P: the pattern every A_ijk term has.
glm::dvec3 wedge(const glm::dvec4& x, const glm::dvec4& y) {
  return glm::dvec3(x) * y.w - x.w * glm::dvec3(y);
}

// Δ^order H_l along a curve's net, zero where an index leaves 0..K.
glm::dvec4 forwardDifference(const std::vector<glm::dvec4>& h, int l, int order) {
  const int K = static_cast<int>(h.size()) - 1;
  if (l < 0 || l + order > K) return glm::dvec4(0.0);
  if (order == 1) return h[l + 1] - h[l];
  return h[l + 2] - 2.0 * h[l + 1] + h[l];
}

double maxNorm(double a, const glm::dvec3& v) { return std::max(a, glm::length(v)); }

}  // namespace

const char* divisionMethodName(DivisionMethod method) {
  switch (method) {
    case DivisionMethod::AbiEzzi: return "abi-ezzi";
    case DivisionMethod::PaperSplit: return "paper";
    case DivisionMethod::Split: return "split";
    case DivisionMethod::Subdivided: return "subdivided";
    case DivisionMethod::CellWise: return "cellwise";
    case DivisionMethod::Directional: return "directional";
    case DivisionMethod::Direct: return "direct";
  }
  return "?";
}

DivisionMethod parseDivisionMethod(const std::string& name) {
  for (DivisionMethod m : {DivisionMethod::AbiEzzi, DivisionMethod::PaperSplit,
                           DivisionMethod::Split, DivisionMethod::Subdivided,
                           DivisionMethod::CellWise, DivisionMethod::Directional,
                           DivisionMethod::Direct})
    if (name == divisionMethodName(m)) return m;
  throw std::invalid_argument("unknown division method '" + name +
                              "' (abi-ezzi, paper, split, subdivided, cellwise, directional or direct)");
}

const char* divisionStatusName(DivisionStatus status) {
  switch (status) {
    case DivisionStatus::Ok: return "ok";
    case DivisionStatus::Capped: return "capped";
    case DivisionStatus::Unbounded: return "unbounded";
    case DivisionStatus::Culled: return "culled";
  }
  return "?";
}

void validateDivisionInput(const RationalBezierCurve& curve, DivisionMethod method) {
  checkedNet(curve, method);
}
void validateDivisionInput(const RationalBezierPatch& patch, DivisionMethod method) {
  checkedNet(patch, method);
}

glm::dvec3 abiEzziCoefficient(const RationalBezierCurve& curve, int i, int j, int k) {
  const std::vector<glm::dvec4>& h = curve.cpw;
  const int K = curve.degree;
  // P' and P'' degree-elevated back to degree K (docs/rational_division.md, eq. D1, D2).
  auto d1 = [&](int l) {
    return double(K - l) * forwardDifference(h, l, 1) + double(l) * forwardDifference(h, l - 1, 1);
  };
  auto d2 = [&](int l) {
    return double((K - l) * (K - l - 1)) * forwardDifference(h, l, 2) +
           double(2 * l * (K - l)) * forwardDifference(h, l - 1, 2) +
           double(l * (l - 1)) * forwardDifference(h, l - 2, 2);
  };
  return wedge(d2(i), h[j]) * h[k].w - 2.0 * wedge(d1(i), h[j]) * d1(k).w;
}

glm::dvec3 abiEzziCoefficientAsPrinted(const RationalBezierCurve& curve, int i, int j, int k) {
  const std::vector<glm::dvec4>& h = curve.cpw;
  const int K = curve.degree;
  (void)k;  // the printed formula never uses k: its last factor repeats i
  const glm::dvec4 second = double((K - i) * (K - j - 1)) * forwardDifference(h, i, 2) +
                            double(2 * i * (K - j)) * forwardDifference(h, i - 1, 2) +
                            double(i * (i - 1)) * forwardDifference(h, i - 2, 2);
  const glm::dvec4 first =
      double(K - i) * forwardDifference(h, i, 1) + double(i) * forwardDifference(h, i - 1, 1);
  return wedge(second, h[j]) * h[k].w - 2.0 * wedge(first, h[j]) * first.w;
}

std::vector<glm::dvec4> degreeKeepingDerivativeU(const std::vector<glm::dvec4>& h, int n, int m) {
  std::vector<glm::dvec4> d(h.size(), glm::dvec4(0.0));
  const int s = m + 1;
  for (int a = 0; a <= n; ++a)
    for (int b = 0; b <= m; ++b) {
      glm::dvec4 r(0.0);
      if (a < n) r += double(n - a) * (h[(a + 1) * s + b] - h[a * s + b]);
      if (a > 0) r += double(a) * (h[a * s + b] - h[(a - 1) * s + b]);
      d[a * s + b] = r;
    }
  return d;
}

std::vector<glm::dvec4> degreeKeepingDerivativeV(const std::vector<glm::dvec4>& h, int n, int m) {
  std::vector<glm::dvec4> d(h.size(), glm::dvec4(0.0));
  const int s = m + 1;
  for (int a = 0; a <= n; ++a)
    for (int b = 0; b <= m; ++b) {
      glm::dvec4 r(0.0);
      if (b < m) r += double(m - b) * (h[a * s + b + 1] - h[a * s + b]);
      if (b > 0) r += double(b) * (h[a * s + b] - h[a * s + b - 1]);
      d[a * s + b] = r;
    }
  return d;
}

DerivativeNets derivativeNets(const HomogeneousNet& net) {
  DerivativeNets d;
  d.d1u = degreeKeepingDerivativeU(net.c, net.n, net.m);
  d.d1v = degreeKeepingDerivativeV(net.c, net.n, net.m);
  d.d2u = degreeKeepingDerivativeU(d.d1u, net.n, net.m);
  d.d2v = degreeKeepingDerivativeV(d.d1v, net.n, net.m);
  d.d11 = degreeKeepingDerivativeV(d.d1u, net.n, net.m);
  return d;
}

WeightRatios vanishedWeightRatios(const HomogeneousNet& net, const std::vector<char>& vanished,
                                  int pieces) {
  const ScalarNet w = weightsOf(net);
  ScalarNet beta(net.n, net.m), omega(net.n, net.m);
  for (size_t k = 0; k < w.c.size(); ++k) {
    beta.c[k] = vanished[k] ? 1.0 : 0.0;
    omega.c[k] = vanished[k] ? 0.0 : std::abs(w.c[k]);
  }
  WeightRatios r;
  r.sigma = 0.0;
  r.sign = 0;
  const int qu = std::max(1, pieces), qv = net.m == 0 ? 1 : qu;
  for (int pu = 0; pu < qu; ++pu)
    for (int pv = 0; pv < qv; ++pv) {
      const double u0 = double(pu) / qu, u1 = double(pu + 1) / qu;
      const double v0 = double(pv) / qv, v1 = double(pv + 1) / qv;
      const ScalarNet wp = subNet(w, u0, u1, v0, v1);
      const ScalarNet bp = subNet(beta, u0, u1, v0, v1);
      const ScalarNet op = subNet(omega, u0, u1, v0, v1);
      const bool positive = std::all_of(wp.c.begin(), wp.c.end(), [](double x) { return x > 0; });
      const bool negative = std::all_of(wp.c.begin(), wp.c.end(), [](double x) { return x < 0; });
      const int sign = positive ? 1 : (negative ? -1 : 0);
      if (sign == 0 || (r.sign != 0 && sign != r.sign)) {
        r.bounded = false;
        return r;
      }
      r.sign = sign;
      for (size_t k = 0; k < wp.c.size(); ++k) {
        r.rho = std::max(r.rho, bp.c[k] / std::abs(wp.c[k]));
        r.sigma = std::max(r.sigma, op.c[k] / std::abs(wp.c[k]));
      }
    }
  return r;
}

ClassMaxima classMaxima(const HomogeneousNet& net, const DerivativeNets& d, int partial,
                        const std::vector<char>& vanished) {
  const std::vector<glm::dvec4>& h = net.c;
  // Partial 3 is S_uv written with the roles of u and v exchanged (S_vu): the same function,
  // a different termwise bound (docs/rational_division.md); splitBounds takes the smaller.
  const bool mixed = partial == 1 || partial == 3;
  const std::vector<glm::dvec4>& second = partial == 0 ? d.d2u : (mixed ? d.d11 : d.d2v);
  // F_ij = first_i ∧ H_j, d_k = firstK_k.w
  const std::vector<glm::dvec4>& first = partial == 2 || partial == 3 ? d.d1v : d.d1u;
  const std::vector<glm::dvec4>& firstK = partial == 0 || partial == 3 ? d.d1u : d.d1v;
  const size_t count = h.size();

  // A_ijk = E_ij w_k − 2 F_ij d_k. Over the k of one class the norm is convex in (w_k, d_k):
  // for non-vanished k, ‖A‖/|w_k| = ‖E − 2F s_k‖ with s_k = d_k/w_k peaks at the extreme s;
  // for vanished k, ‖E w − 2F d‖ peaks at a corner of the (w, d) box.
  double sMin = INFINITY, sMax = -INFINITY, wzMin = INFINITY, wzMax = -INFINITY,
         dzMin = INFINITY, dzMax = -INFINITY;
  for (size_t k = 0; k < count; ++k) {
    const double wk = h[k].w, dk = firstK[k].w;
    if (vanished[k]) {
      wzMin = std::min(wzMin, wk), wzMax = std::max(wzMax, wk);
      dzMin = std::min(dzMin, dk), dzMax = std::max(dzMax, dk);
    } else {
      sMin = std::min(sMin, dk / wk), sMax = std::max(sMax, dk / wk);
    }
  }
  const bool anyKept = sMin <= sMax, anyVanished = wzMin <= wzMax;

  ClassMaxima result;
  for (size_t i = 0; i < count; ++i)
    for (size_t j = 0; j < count; ++j) {
      glm::dvec3 e = wedge(second[i], h[j]);
      if (partial == 1) e += wedge(d.d1u[i], d.d1v[j]);
      if (partial == 3) e += wedge(d.d1v[i], d.d1u[j]);
      const glm::dvec3 f = wedge(first[i], h[j]);
      const double den = (vanished[i] ? 1.0 : std::abs(h[i].w)) *
                         (vanished[j] ? 1.0 : std::abs(h[j].w));
      const int cls = 4 * vanished[i] + 2 * vanished[j];
      if (anyKept) {
        double v = maxNorm(glm::length(e - 2.0 * f * sMin), e - 2.0 * f * sMax);
        result.b[cls] = std::max(result.b[cls], v / den);
      }
      if (anyVanished) {
        double v = 0.0;
        for (double wk : {wzMin, wzMax})
          for (double dk : {dzMin, dzMax}) v = maxNorm(v, e * wk - 2.0 * f * dk);
        result.b[cls + 1] = std::max(result.b[cls + 1], v / den);
      }
    }
  return result;
}

double combineClasses(const ClassMaxima& classes, double rho, double sigma) {
  double sum = 0.0;
  for (int cls = 0; cls < 8; ++cls) {
    if (classes.b[cls] == 0.0) continue;
    const int nVanished = (cls >> 2 & 1) + (cls >> 1 & 1) + (cls & 1);
    sum += classes.b[cls] * std::pow(sigma, 3 - nVanished) * std::pow(rho, nVanished);
  }
  return sum;
}

SecondDerivativeBounds splitBounds(const HomogeneousNet& net, const DivisionOptions& options) {
  double maxAbsW = 0.0, minNonzeroW = INFINITY;
  bool anyNegative = false, anyPositive = false;
  for (const glm::dvec4& h : net.c) {
    maxAbsW = std::max(maxAbsW, std::abs(h.w));
    if (h.w != 0.0) minNonzeroW = std::min(minNonzeroW, std::abs(h.w));
    anyNegative = anyNegative || h.w < 0.0;
    anyPositive = anyPositive || h.w > 0.0;
  }
  std::vector<char> vanished(net.c.size(), 0);
  const double threshold =
      options.method == DivisionMethod::Split ? options.zeroClassThreshold * maxAbsW : 0.0;
  bool anyVanished = false;
  for (size_t k = 0; k < net.c.size(); ++k) {
    vanished[k] = std::abs(net.c[k].w) <= threshold;
    anyVanished = anyVanished || vanished[k];
  }

  SecondDerivativeBounds bounds;
  double rho = 0.0, sigma = 1.0;
  if (options.method == DivisionMethod::PaperSplit) {
    rho = 1.0 / minNonzeroW;  // eq. 4.2: a vanished denominator becomes the smallest weight
  } else if (anyVanished || (anyNegative && anyPositive)) {
    const WeightRatios r = vanishedWeightRatios(net, vanished, options.ratioPieces);
    if (!r.bounded) {
      bounds.bounded = false;
      bounds.uu = bounds.uv = bounds.vv = INFINITY;
      return bounds;
    }
    rho = r.rho;
    sigma = r.sigma;
  }
  const DerivativeNets d = derivativeNets(net);
  double* out[3] = {&bounds.uu, &bounds.uv, &bounds.vv};
  for (int partial = 0; partial < 3; ++partial) {
    if (net.m == 0 && partial > 0) break;
    *out[partial] = combineClasses(classMaxima(net, d, partial, vanished), rho, sigma);
  }
  if (net.m > 0)
    bounds.uv = std::min(bounds.uv, combineClasses(classMaxima(net, d, 3, vanished), rho, sigma));
  return bounds;
}

Divisions divisionsFromBounds(const SecondDerivativeBounds& bounds, double tolerance,
                              int maxPerDirection) {
  if (!(tolerance > 0.0) || !std::isfinite(tolerance))
    throw std::invalid_argument("division count: the tolerance must be a finite number > 0, got " +
                                std::to_string(tolerance));
  if (maxPerDirection < 1)
    throw std::invalid_argument("division count: maxPerDirection must be ≥ 1");
  Divisions r;
  r.bounds = bounds;
  const double a = bounds.uu, b = bounds.uv, c = bounds.vv, T = 8.0 * tolerance;
  if (!bounds.bounded || !std::isfinite(a + b + c)) {
    r.status = DivisionStatus::Unbounded;
    r.nu = r.nv = maxPerDirection;
    r.realU = r.realV = INFINITY;
    return r;
  }
  double nu = 1.0, nv = 1.0;
  if (a + 2.0 * b + c > T) {
    // Smallest real N_u·N_v with a/N_u² + 2b/(N_u N_v) + c/N_v² = T: at N_u/N_v = √(a/c) the
    // product is 2(√(ac) + b)/T. Where that puts one count below 1 it is held at 1 and the
    // other solves the quadratic (in the stable form, no cancellation).
    if (a > 0.0 && c > 0.0) {
      const double ratio = std::sqrt(a / c), product = 2.0 * (std::sqrt(a * c) + b) / T;
      nu = std::sqrt(product * ratio);
      nv = std::sqrt(product / ratio);
    } else if (a == 0.0 && c == 0.0) {
      nu = nv = std::sqrt(2.0 * b / T);
    } else if (c == 0.0) {
      nv = 0.0;
    } else {
      nu = 0.0;
    }
    if (nv < 1.0) {
      nv = 1.0;
      nu = (b + std::sqrt(b * b + a * (T - c))) / (T - c);
    } else if (nu < 1.0) {
      nu = 1.0;
      nv = (b + std::sqrt(b * b + c * (T - a))) / (T - a);
    }
  }
  r.realU = std::max(1.0, nu);
  r.realV = std::max(1.0, nv);
  auto toCount = [&](double real) {
    if (real > maxPerDirection) {
      r.status = DivisionStatus::Capped;
      return maxPerDirection;
    }
    return static_cast<int>(std::ceil(real));
  };
  r.nu = toCount(r.realU);
  r.nv = toCount(r.realV);
  return r;
}

namespace {

// Subdivided, CellWise, Directional and Direct (which start from the subdivided counts) take
// the subdivided bound.
bool searchesCells(DivisionMethod method) {
  return method == DivisionMethod::CellWise || method == DivisionMethod::Directional ||
         method == DivisionMethod::Direct;
}

SecondDerivativeBounds boundsOf(const HomogeneousNet& net, const DivisionOptions& options) {
  const bool subdivided = options.method == DivisionMethod::Subdivided ||
                          searchesCells(options.method);
  return subdivided ? subdividedBounds(net, options) : splitBounds(net, options);
}

Divisions divisionsOf(const HomogeneousNet& net, const DivisionOptions& options) {
  const SecondDerivativeBounds bounds = boundsOf(net, options);
  if (!bounds.visible) {
    Divisions r;
    r.bounds = bounds;
    r.status = DivisionStatus::Culled;
    r.nu = r.nv = 0;
    r.realU = r.realV = 0.0;
    return r;
  }
  const Divisions global = divisionsFromBounds(bounds, options.tolerance, options.maxPerDirection);
  return searchesCells(options.method) ? cellwiseDivisions(net, options, global) : global;
}

}  // namespace

SecondDerivativeBounds secondDerivativeBounds(const RationalBezierPatch& patch,
                                              const DivisionOptions& options) {
  return boundsOf(checkedNet(patch, options.method), options);
}

SecondDerivativeBounds secondDerivativeBounds(const RationalBezierCurve& curve,
                                              const DivisionOptions& options) {
  return boundsOf(checkedNet(curve, options.method), options);
}

Divisions patchDivisions(const RationalBezierPatch& patch, const DivisionOptions& options) {
  return divisionsOf(checkedNet(patch, options.method), options);
}

Divisions curveDivisions(const RationalBezierCurve& curve, const DivisionOptions& options) {
  return divisionsOf(checkedNet(curve, options.method), options);
}

RationalBezierPatch substituteZeroWeights(const RationalBezierPatch& patch, double value) {
  RationalBezierPatch r = patch;
  for (glm::dvec4& h : r.cpw)
    if (h.w == 0.0) h.w = value;
  return r;
}

}  // namespace tessera
