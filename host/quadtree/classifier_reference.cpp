// The double-precision reference backend of NodeClassifier: the algorithm of
// shaders/lib/quadtree_classify.h (same samples, same Newton steps, same tests), written
// again on the independent double kernel (bicubic.h, bezier.h, rational.h, surface_normal.h,
// curvature.h), so that it checks the shared fp32 text rather than repeating it. Bicubic and
// general patches (any degree, rational) alike. Rule T: the same bound in double, on the
// sub-net of geometry/homogeneous_net.h and, for rational patches, the `split` bounds of
// division/count.h (no fp32 guard: this is the exact value the guard protects).
#include <algorithm>
#include <cmath>

#include "common/stopwatch.h"
#include "division/count.h"
#include "geometry/homogeneous_net.h"
#include "geometry/bezier.h"
#include "geometry/bicubic.h"
#include "geometry/curvature.h"
#include "geometry/rational.h"
#include "quadtree/quadtree.h"
#include "geometry/surface_normal.h"

namespace tessera {
namespace {

using glm::dvec2;
using glm::dvec3;

constexpr double kEps = 1e-12;  // ε of docs/conventions.md in double

struct Frame {
  dvec3 p, tu, tv, n;
  double kappa;
};

// One patch as the double kernel evaluates it, built from the fp32 values the GPU sees.
struct PatchContext {
  enum Kind { kBicubic, kPolynomial, kRational } kind = kBicubic;
  BicubicNet net;
  BezierPatch polynomial;
  RationalBezierPatch rational;
  double scale = 0;

  SurfaceDerivatives derivs(double u, double v) const {
    if (kind == kBicubic) return bicubicDerivatives(net, u, v);
    if (kind == kPolynomial) return patchDerivatives(polynomial, u, v);
    return rationalPatchDerivatives(rational, u, v);
  }
};

PatchContext generalContext(const GeneralPatchSet& set, size_t index) {
  const gpu::GeneralPatch& g = set.patches[index];
  PatchContext c;
  c.kind = g.rational ? PatchContext::kRational : PatchContext::kPolynomial;
  const size_t count = size_t(g.degreeU + 1) * size_t(g.degreeV + 1);
  c.polynomial.degreeU = c.rational.degreeU = int(g.degreeU);
  c.polynomial.degreeV = c.rational.degreeV = int(g.degreeV);
  for (size_t k = 0; k < count; ++k) {
    const glm::dvec4 h(set.points.at(g.firstPoint + k));
    c.polynomial.cp.push_back(dvec3(h));
    c.rational.cpw.push_back(h);
  }
  c.scale = g.rational ? controlNetDiagonal(c.rational) : controlNetDiagonal(c.polynomial);
  return c;
}

dvec3 unitOrZero(const dvec3& v, double tol) {
  double len = glm::length(v);
  return len > tol ? v / len : dvec3(0.0);
}

Frame frameAt(const PatchContext& p, double u, double v) {
  SurfaceDerivatives d = p.derivs(u, v);
  Frame f;
  f.p = d.p;
  f.tu = unitOrZero(d.pu, kEps * p.scale);
  f.tv = unitOrZero(d.pv, kEps * p.scale);
  f.n = unitNormal(d, u, v, p.scale, kEps);
  f.kappa = surfaceCurvature(d, p.scale, kEps).kappa;
  return f;
}

double kappaAt(const PatchContext& p, double u, double v) {
  return surfaceCurvature(p.derivs(u, v), p.scale, kEps).kappa;
}

double angleTest(const dvec3& a, const dvec3& b) {
  if (glm::dot(a, a) == 0.0 || glm::dot(b, b) == 0.0) return 0.0;
  return 1.0 - glm::dot(a, b);
}

// The node's width on the model against fp32's unit in the last place of its largest
// coordinate, as resolvesChildren in lib/quadtree_classify.h (the same bound, in double).
bool resolvesChildren(const Frame& s, const Frame& c0, const Frame& c1, const Frame& c2,
                      const Frame& c3) {
  const auto height = [](const dvec3& a, const dvec3& b, const dvec3& c) {
    const double longest = std::sqrt(std::max({glm::dot(b - a, b - a), glm::dot(c - a, c - a),
                                               glm::dot(c - b, c - b)}));
    return longest > 0 ? glm::length(glm::cross(b - a, c - a)) / longest : 0.0;
  };
  const double width = std::max({height(s.p, c0.p, c1.p), height(s.p, c1.p, c2.p),
                                 height(s.p, c2.p, c3.p), height(s.p, c3.p, c0.p)});
  double largest = 0;
  for (const Frame* f : {&s, &c0, &c1, &c2, &c3})
    for (int k = 0; k < 3; ++k) largest = std::max(largest, std::fabs(f->p[k]));
  return largest > 0 && width >= double(gpu::kResolvedWidthUlps) * largest * 0x1p-23;
}

struct Rect {
  double u0, v0, u1, v1;
  double u(double s) const { return u0 + (u1 - u0) * s; }
  double v(double t) const { return v0 + (v1 - v0) * t; }
};

double kappaLocal(const PatchContext& p, const Rect& r, double s, double t) {
  return kappaAt(p, r.u(s), r.v(t));
}

void sampledMaxima(const PatchContext& p, const Rect& r, int samples, dvec3& best, dvec3& second) {
  best = second = dvec3(0.5, 0.5, -1.0);
  for (int a = 0; a < samples; ++a)
    for (int b = 0; b < samples; ++b) {
      double s = double(a + 1) / double(samples + 1), t = double(b + 1) / double(samples + 1);
      double k = kappaLocal(p, r, s, t);
      if (k > best.z) {
        second = best;
        best = dvec3(s, t, k);
      } else if (k > second.z) {
        second = dvec3(s, t, k);
      }
    }
}

constexpr double kGradientStep = 1e-3, kHessianStep = 2e-2;

// One step of the trust-region searches from x (where κ = kx) to the trial point y: taken if κ
// grows there, and the radius doubles (at most 0.25); else the radius shrinks to a quarter.
void trustRegionStep(const PatchContext& p, const Rect& r, dvec2 y, dvec2& x, double& kx,
                     double& radius) {
  double ky = kappaLocal(p, r, y.x, y.y);
  if (ky > kx) {
    x = y;
    kx = ky;
    radius = std::min(2.0 * radius, 0.25);
  } else {
    radius *= 0.25;
  }
}

dvec3 newtonMaximum(const PatchContext& p, const Rect& r, dvec3 seed, int samples) {
  const double hg = kGradientStep, hh = kHessianStep;
  dvec2 x(seed.x, seed.y);
  double kx = seed.z;
  double radius = 0.5 / double(samples + 1);
  for (int it = 0; it < gpu::kNewtonIterations; ++it) {
    double gs = (kappaLocal(p, r, x.x + hg, x.y) - kappaLocal(p, r, x.x - hg, x.y)) / (2 * hg);
    double gt = (kappaLocal(p, r, x.x, x.y + hg) - kappaLocal(p, r, x.x, x.y - hg)) / (2 * hg);
    double hss = (kappaLocal(p, r, x.x + hh, x.y) - 2 * kx + kappaLocal(p, r, x.x - hh, x.y)) /
                 (hh * hh);
    double htt = (kappaLocal(p, r, x.x, x.y + hh) - 2 * kx + kappaLocal(p, r, x.x, x.y - hh)) /
                 (hh * hh);
    double hst = (kappaLocal(p, r, x.x + hh, x.y + hh) - kappaLocal(p, r, x.x + hh, x.y - hh) -
                  kappaLocal(p, r, x.x - hh, x.y + hh) + kappaLocal(p, r, x.x - hh, x.y - hh)) /
                 (4 * hh * hh);
    double det = hss * htt - hst * hst;
    dvec2 step(gs, gt);
    if (hss < 0.0 && det > 0.0)
      step = dvec2(-(htt * gs - hst * gt) / det, -(hss * gt - hst * gs) / det);
    double slen = glm::length(step);
    if (slen > radius) step *= radius / slen;
    dvec2 y = glm::clamp(x + step, dvec2(0.0), dvec2(1.0));
    trustRegionStep(p, r, y, x, kx, radius);
  }
  return dvec3(x.x, x.y, kx);
}

dvec3 boundaryMaximum(const PatchContext& p, const Rect& r, int samples) {
  dvec3 best(0.5, 0.5, -1.0);
  int bestEdge = 0;
  for (int e = 0; e < 4; ++e)
    for (int a = 0; a < samples; ++a) {
      double q = double(a + 1) / double(samples + 1);
      double s = e == 0 ? q : (e == 1 ? 1.0 : (e == 2 ? q : 0.0));
      double t = e == 0 ? 0.0 : (e == 1 ? q : (e == 2 ? 1.0 : q));
      double k = kappaLocal(p, r, s, t);
      if (k > best.z) {
        best = dvec3(s, t, k);
        bestEdge = e;
      }
    }
  const double hg = kGradientStep, hh = kHessianStep;
  dvec2 dir = (bestEdge == 0 || bestEdge == 2) ? dvec2(1, 0) : dvec2(0, 1);
  dvec2 x(best.x, best.y);
  double kx = best.z;
  double radius = 0.5 / double(samples + 1);
  for (int it = 0; it < gpu::kNewtonIterations; ++it) {
    double g = (kappaLocal(p, r, x.x + hg * dir.x, x.y + hg * dir.y) -
                kappaLocal(p, r, x.x - hg * dir.x, x.y - hg * dir.y)) /
               (2 * hg);
    double h2 = (kappaLocal(p, r, x.x + hh * dir.x, x.y + hh * dir.y) - 2 * kx +
                 kappaLocal(p, r, x.x - hh * dir.x, x.y - hh * dir.y)) /
                (hh * hh);
    double step = std::clamp(h2 < 0.0 ? -g / h2 : g, -radius, radius);
    dvec2 y = glm::clamp(x + step * dir, dvec2(0.0), dvec2(1.0));
    trustRegionStep(p, r, y, x, kx, radius);
  }
  return dvec3(x.x, x.y, kx);
}

dvec2 splitPointLocal(const PatchContext& p, const Rect& r, SplitRule rule, int samples) {
  if (rule == SplitRule::Midpoint) return dvec2(0.5);
  dvec3 best, second;
  sampledMaxima(p, r, samples, best, second);
  if (rule == SplitRule::TrueMax) {
    for (dvec3 c : {newtonMaximum(p, r, best, samples), newtonMaximum(p, r, second, samples),
                    boundaryMaximum(p, r, samples)})
      if (c.z > best.z) best = c;
  }
  if (!(best.z > 0.0)) return dvec2(0.5);
  double m = gpu::kSplitMargin;
  return glm::clamp(dvec2(best.x, best.y), dvec2(m), dvec2(1.0 - m));
}

// Rule T: (M_ss, M_st, M_tt) of the node in local coordinates (docs/quadtree.md, "Rule T"),
// and for polynomial nets the centred form's C (the nets' bounding-box centres) and
// m = (m_ss, m_st, m_tt) (their largest distances from them; "A tighter bound").
struct SecondBounds {
  double ss = 0, st = 0, tt = 0;
  dvec3 css{0.0}, cst{0.0}, ctt{0.0};
  double mss = 0, mst = 0, mtt = 0;
  double spreadShare = 1.0;  // of m, in the grid estimate: lib/tolerance_bound.h's spread.w
};

// One second-difference net's largest norm, bounding-box centre and spread, scaled by c.
void netTerms(const std::vector<dvec3>& net, double c, double& largest, dvec3& centre,
              double& spread) {
  dvec3 lo(INFINITY), hi(-INFINITY);
  largest = 0;
  for (const dvec3& d : net) lo = glm::min(lo, d), hi = glm::max(hi, d), largest = std::max(largest, glm::length(d));
  centre = net.empty() ? dvec3(0.0) : 0.5 * (lo + hi);
  spread = 0;
  for (const dvec3& d : net) spread = std::max(spread, glm::length(d - centre));
  largest *= c, centre *= c, spread *= c;
}

SecondBounds polynomialBounds(const HomogeneousNet& net) {
  SecondBounds b;
  const int n = net.n, m = net.m;
  std::vector<dvec3> ss, st, tt;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j) {
      const dvec3 p(net.at(i, j));
      if (i + 2 <= n) ss.push_back(dvec3(net.at(i + 2, j)) - 2.0 * dvec3(net.at(i + 1, j)) + p);
      if (j + 2 <= m) tt.push_back(dvec3(net.at(i, j + 2)) - 2.0 * dvec3(net.at(i, j + 1)) + p);
      if (i < n && j < m)
        st.push_back(dvec3(net.at(i + 1, j + 1)) - dvec3(net.at(i + 1, j)) -
                     dvec3(net.at(i, j + 1)) + p);
    }
  netTerms(ss, double(n * (n - 1)), b.ss, b.css, b.mss);
  netTerms(st, double(n * m), b.st, b.cst, b.mst);
  netTerms(tt, double(m * (m - 1)), b.tt, b.ctt, b.mtt);
  b.spreadShare = gpu::kToleranceSpreadShare;
  return b;
}

// gridNumerator's W for the grid estimate: the smaller of the two diagonals'.
constexpr uint32_t kBetterDiagonal = 3;

// W(C) of lib/tolerance_bound.h's quadraticPartBound, in double.
double quadraticPartBound(const dvec3& ss, const dvec3& st, const dvec3& tt) {
  return std::max({glm::length(ss + tt + 2.0 * st), glm::length(ss + tt - 2.0 * st),
                   glm::length(ss + st), glm::length(ss - st), glm::length(tt + st),
                   glm::length(tt - st)});
}

// W₁(C) of lib/tolerance_bound.h's diagonalQuadraticPartBound (triangles along the main
// diagonal; with −st the anti-diagonal's W₂), in double.
double diagonalQuadraticPartBound(const dvec3& ss, const dvec3& st, const dvec3& tt) {
  return std::max({glm::length(ss + tt + 2.0 * st), glm::length(ss + tt), glm::length(ss + st),
                   glm::length(tt + st), glm::length(ss), glm::length(tt)});
}

// W of the diagonal asked for (gpu::kTolerance*Diagonal); for the grid estimate, the better one.
double quadraticPartBound(const dvec3& ss, const dvec3& st, const dvec3& tt, uint32_t diagonal) {
  if (diagonal == gpu::kToleranceMainDiagonal) return diagonalQuadraticPartBound(ss, st, tt);
  if (diagonal == gpu::kToleranceAntiDiagonal) return diagonalQuadraticPartBound(ss, -st, tt);
  return quadraticPartBound(ss, st, tt);
}

// 8·k_u²·k_v² × the bound of a child of the node split k_u × k_v, the spreads counted by
// spreadShare (toleranceGridNumerator: the better diagonal's W), or with spreadShare 1 the
// node's own bound for triangles along `diagonal`.
double gridNumerator(const SecondBounds& m, double uu, double uv, double vv, double spreadShare,
                     uint32_t diagonal) {
  const double plain = m.ss * vv + 2.0 * m.st * uv + m.tt * uu;
  const dvec3 ss = vv * m.css, st = uv * m.cst, tt = uu * m.ctt;
  const double w = diagonal == kBetterDiagonal
                       ? std::min(diagonalQuadraticPartBound(ss, st, tt),
                                  diagonalQuadraticPartBound(ss, -st, tt))
                       : quadraticPartBound(ss, st, tt, diagonal);
  const double centred = w + spreadShare * (m.mss * vv + 2.0 * m.mst * uv + m.mtt * uu);
  return std::min(plain, centred);
}

// The patch's homogeneous net moved to a control point O (P_h − w·O), the local frame of the
// fp32 bound (polynomial: P₀₀; rational: the point of largest weight): the bounds are
// translation-invariant in exact arithmetic, and here no large coordinate enters the double
// restriction either.
HomogeneousNet contextNet(const PatchContext& p) {
  HomogeneousNet net = [&] {
    if (p.kind == PatchContext::kRational) return toNet(p.rational);
    const bool bicubic = p.kind == PatchContext::kBicubic;
    const int n = bicubic ? 3 : p.polynomial.degreeU, m = bicubic ? 3 : p.polynomial.degreeV;
    HomogeneousNet h(n, m);
    for (int k = 0; k < (n + 1) * (m + 1); ++k)
      h.c[size_t(k)] = glm::dvec4(bicubic ? p.net[k] : p.polynomial.cp[size_t(k)], 1.0);
    return h;
  }();
  dvec3 origin(0.0);  // the control point of largest weight, as tolerance_general.h chooses
  double heaviest = 0;
  for (const auto& c : net.c)
    if (c.w > heaviest) heaviest = c.w, origin = dvec3(c) / c.w;
  for (auto& c : net.c) c = glm::dvec4(dvec3(c) - c.w * origin, c.w);
  return net;
}

SecondBounds toleranceBounds(const PatchContext& p, const Rect& r) {
  const HomogeneousNet sub = subNet(contextNet(p), r.u0, r.u1, r.v0, r.v1);
  if (p.kind != PatchContext::kRational) return polynomialBounds(sub);
  DivisionOptions options;
  options.method = DivisionMethod::Split;
  options.ratioPieces = gpu::kToleranceRatioPieces;
  SecondDerivativeBounds d = secondDerivativeBounds(toPatch(sub), options);
  SecondBounds b;  // no centred form: C = 0, m = M
  if (!d.bounded) d.uu = d.uv = d.vv = INFINITY;
  b.ss = b.mss = d.uu, b.st = b.mst = d.uv, b.tt = b.mtt = d.vv;
  return b;
}

// The fewest equal children k_u × k_v (each ≤ the cap) whose estimated bound
// gridNumerator/(8·k_u²·k_v²) is within δ, as k_u | k_v << 8; 0 if none
// (the double twin of toleranceGridCounts in lib/tolerance_bound.h, without its fp32 guard).
uint32_t toleranceGridCounts(const SecondBounds& m, double tolerance, uint32_t cap) {
  uint32_t best = 0, bestCount = cap * cap + 1;
  double bestEstimate = 0;
  for (uint32_t ku = 1; ku <= cap; ++ku)
    for (uint32_t kv = 1; kv <= cap && ku * kv <= bestCount; ++kv) {
      if (ku * kv < 2) continue;
      const double fu = ku, fv = kv;
      const double estimate = gridNumerator(m, fu * fu, fu * fv, fv * fv, m.spreadShare,
                                            kBetterDiagonal) /
                              (fu * fu * fv * fv) / 8.0;
      if (!(estimate <= tolerance)) continue;
      if (ku * kv < bestCount || estimate < bestEstimate) {
        best = ku | (kv << 8);
        bestCount = ku * kv;
        bestEstimate = estimate;
      }
      break;
    }
  return best;
}

gpu::NodeDecision toleranceDecision(const PatchContext& p, const gpu::QuadNode& node,
                                    const QuadtreeOptions& o) {
  Rect r{node.rect.x, node.rect.y, node.rect.z, node.rect.w};
  const SecondBounds m = toleranceBounds(p, r);
  const double a = m.ss + m.st, b = m.tt + m.st;
  const double bound = gridNumerator(m, 1, 1, 1, 1.0, gpu::kToleranceAnyDiagonal) / 8.0;
  const double boundMain = gridNumerator(m, 1, 1, 1, 1.0, gpu::kToleranceMainDiagonal) / 8.0;
  const double boundAnti = gridNumerator(m, 1, 1, 1, 1.0, gpu::kToleranceAntiDiagonal) / 8.0;
  gpu::NodeDecision d{};
  d.split = gpu::vec4(float(r.u(0.5)), float(r.v(0.5)), 0.0f, 0.0f);
  d.linearity = float(a + b > 0.0 ? a / (a + b) : 0.5);
  // The better diagonal's bound where it is smaller (the leaf keeps to that diagonal).
  const double boundDiagonal = std::min(boundMain, boundAnti);
  const bool oneDiagonal = boundDiagonal < bound;
  d.flatness = float(oneDiagonal ? boundDiagonal : bound);
  if (std::min(bound, boundDiagonal) <= o.tolerance) {
    d.cause = gpu::kCauseWithinTolerance;
    if (oneDiagonal)
      d.pad = boundAnti < boundMain ? gpu::kToleranceAntiDiagonal : gpu::kToleranceMainDiagonal;
  } else if (node.level >= o.maxDepth) {
    d.cause = gpu::kCauseMaxDepth;
  } else if (std::min(r.u1 - r.u0, r.v1 - r.v0) < o.minSize) {
    d.cause = gpu::kCauseMinSize;
  } else if (const uint32_t grid = toleranceGridCounts(m, o.tolerance, o.toleranceSplitCap)) {
    d.cause = gpu::kCauseSplitGrid;
    d.pad = grid;
  } else {
    const bool splitU = !(a < 0.5 * b), splitV = !(b < 0.5 * a);
    d.cause = splitU && !splitV   ? gpu::kCauseSplitU
              : splitV && !splitU ? gpu::kCauseSplitV
                                  : gpu::kCauseSplit;
  }
  return d;
}

gpu::NodeDecision classifyNode(const PatchContext& p, const gpu::QuadNode& node,
                               const QuadtreeOptions& o) {
  if (o.rule == SplitRule::Tolerance) return toleranceDecision(p, node, o);
  Rect r{node.rect.x, node.rect.y, node.rect.z, node.rect.w};
  dvec2 local = splitPointLocal(p, r, o.rule, o.samples);
  double us = r.u(local.x), vs = r.v(local.y);
  Frame c0 = frameAt(p, r.u0, r.v0), c1 = frameAt(p, r.u1, r.v0);
  Frame c2 = frameAt(p, r.u1, r.v1), c3 = frameAt(p, r.u0, r.v1);
  Frame sp = frameAt(p, us, vs);
  double lin = std::max({angleTest(c0.tu, c1.tu), angleTest(c1.tv, c2.tv),
                         angleTest(c3.tu, c2.tu), angleTest(c0.tv, c3.tv)});
  double flat = std::max({angleTest(c0.n, c1.n), angleTest(c1.n, c2.n), angleTest(c2.n, c3.n),
                          angleTest(c3.n, c0.n), angleTest(c0.n, sp.n), angleTest(c1.n, sp.n),
                          angleTest(c2.n, sp.n), angleTest(c3.n, sp.n)});
  gpu::NodeDecision d{};
  d.split = gpu::vec4(float(us), float(vs), float(sp.kappa), 0.0f);
  d.linearity = float(lin);
  d.flatness = float(flat);
  if (lin < o.linearity && flat < o.flatness)
    d.cause = gpu::kCauseFlat;
  else if (node.level >= o.maxDepth)
    d.cause = gpu::kCauseMaxDepth;
  else if (std::min(r.u1 - r.u0, r.v1 - r.v0) < o.minSize || !resolvesChildren(sp, c0, c1, c2, c3))
    d.cause = gpu::kCauseMinSize;
  else
    d.cause = gpu::kCauseSplit;
  return d;
}

class ReferenceClassifier final : public NodeClassifier {
 public:
  std::string name() const override { return "cpu-double"; }

  void beginTree(const PatchSet& patches) override {
    if (patches.isBicubic())
      beginBicubic(patches.bicubic());
    else
      beginGeneral(patches.general());
  }

  void classify(const PatchSet& patches, const std::vector<gpu::QuadNode>& nodes,
                const QuadtreeOptions& options, std::vector<gpu::NodeDecision>& decisions,
                LevelStats& stats) override {
    if (contexts_.size() != patches.size())
      throw std::logic_error("ReferenceClassifier: classify() without beginTree()");
    const Stopwatch stopwatch;
    decisions.resize(nodes.size());
    for (size_t i = 0; i < nodes.size(); ++i)
      decisions[i] = classifyNode(contexts_[nodes[i].patchIndex], nodes[i], options);
    stats.classifyMs += stopwatch.elapsedMs();
  }

 private:
  void beginBicubic(const std::vector<gpu::BicubicPatch>& patches) {
    contexts_.assign(patches.size(), PatchContext());
    for (size_t i = 0; i < patches.size(); ++i) {
      BezierPatch bp;
      bp.cp.resize(16);
      for (int k = 0; k < 16; ++k) {
        contexts_[i].net[k] = dvec3(glm::vec3(patches[i].cp[k]));
        bp.cp[k] = contexts_[i].net[k];
      }
      contexts_[i].scale = controlNetDiagonal(bp);
    }
  }

  void beginGeneral(const GeneralPatchSet& patches) {
    contexts_.clear();
    for (size_t i = 0; i < patches.size(); ++i) contexts_.push_back(generalContext(patches, i));
  }

  std::vector<PatchContext> contexts_;
};

}  // namespace

std::unique_ptr<NodeClassifier> makeReferenceClassifier() {
  return std::make_unique<ReferenceClassifier>();
}

}  // namespace tessera
