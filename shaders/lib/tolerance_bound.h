// Rule T (issue 15; docs/quadtree.md, "Rule T: tolerance") in fp32: the node's proven bound
// on the parametric deviation of every triangle it can emit, (M_ss + 2·M_st + M_tt)/8 from
// bounds M of the second derivatives in node-local coordinates (s, t) ∈ [0,1]², and the
// decision: leaf within δ, or split into k_u × k_v equal children (toleranceGridCounts), or
// along u, v or both at the node's midpoint.
// Compiled as GLSL (quadtree.comp.glsl, quadtree_general.comp.glsl) and as C++ (the mirrors)
// from this one text, at namespace scope. Include shared_glsl_cpp.h and layout.h first.
#ifndef TESSERA_TOLERANCE_BOUND_H
#define TESSERA_TOLERANCE_BOUND_H

// The fp32 bound is (1 + 2⁻¹⁰)·(M_ss + 2·M_st + M_tt)/8 + guard: the factor covers the
// rounding of the bound's own arithmetic (norms, products, the widths h), the guard the
// rounding of the restricted nets' coordinates (docs/quadtree.md, "fp32"). Polynomial nets
// are bounded through their second-difference nets, restricted to the node and scaled by h²:
// the guard is 2⁻²⁶·Σ c·h²·(2·F₁ + (1 + 6·(d_u + d_v))·F₂) (F₁, F₂ the largest |component| of
// the first and second differences, d_u × d_v the difference net's degrees), which depends
// on neither the position nor the units of the model. Rational nets, translated to their
// control point O of largest weight, keep 2⁻²⁰·(n² + m²)·max|P − O| (not proven:
// tolerance_net.h).
const float kToleranceRelativeGuard = 1.0009765625f;  // 1 + 2⁻¹⁰
const float kToleranceRoundingGuard = 9.5367431640625e-7f;  // 2⁻²⁰ (rational)
// u/4 = 2⁻²⁶ with u = 2⁻²⁴: at least (√3/8)·u (a norm of three coordinates, /8 of the bound)
// with room for the (1 + u)ᵏ of the convex combinations (polynomial).
const float kToleranceDifferenceGuard = 1.4901161193847656e-8f;  // 2⁻²⁶
// A bound no δ accepts: where w may vanish on the node (rational nets the weight ratios
// cannot bound), the node splits in both directions.
const float kToleranceUnbounded = 1.0e30f;

// One row of Bernstein coefficients (at most kGeneralMaxOrder; a shader for bicubic patches
// alone defines TOLERANCE_ROW_ORDER 4, its rows' largest order: lavapipe compiles the pipeline
// at every run, and unrolling the restriction's loops to 4 rather than 8 costs it a fifth less.
// The loops skip the entries past the degree either way, so the arithmetic is the same).
#ifndef TOLERANCE_ROW_ORDER
#define TOLERANCE_ROW_ORDER kGeneralMaxOrder
#endif
// The bicubic shaders also define TOLERANCE_UNROLL [[unroll]]: their loops have constant trip
// counts (the degrees are constants there) and neither break nor continue, the entries past
// the degree skipped by a test, so spirv-opt unrolls them (run twice: it unrolls a level of
// nesting per run) and lavapipe gets straight-line code instead of unrolling 48 loops itself at
// every run, which was most of its compile (bench/HISTORY.md, "The Vulkan path's fixed cost").
// The bicubic C++ mirror (host/quadtree/classify_mirror.cpp) takes the same form with GCC's
// unroll pragma: straight-line code there too, rule T's CPU tree ~25% faster. Elsewhere (the
// general shaders, whose degrees vary per patch, and their mirrors) the loops stay loops and
// break at the degree. TOLERANCE_WHILE(c) { … } runs the block while c holds: the unrolled
// forms test c at every iteration, the others break at the first where it fails.
#ifndef TOLERANCE_UNROLL
#define TOLERANCE_UNROLL
#define TOLERANCE_WHILE(condition) \
  if (!(condition)) break;
#else
#define TOLERANCE_WHILE(condition) if (condition)
#endif
struct BernsteinRow4 {
  vec4 c[TOLERANCE_ROW_ORDER];
};

// The row's coefficients restricted to [t0, t1] (0 ≤ t0 < t1 ≤ 1) and reparametrised to
// [0, 1]: split at t1 keeping the left piece, then at t0/t1 keeping the right piece (de
// Casteljau both times), as restrictCoefficients in host/geometry/homogeneous_net.h.
void restrictBernsteinRow(INOUT(BernsteinRow4) row, int degree, float t0, float t1) {
  vec4 left[TOLERANCE_ROW_ORDER];
  left[0] = row.c[0];
  PRECISE float om1 = 1.0f - t1;
  TOLERANCE_UNROLL for (int r = 1; r < TOLERANCE_ROW_ORDER; ++r) {
    TOLERANCE_WHILE(r <= degree) {
      TOLERANCE_UNROLL for (int k = 0; k < TOLERANCE_ROW_ORDER - 1; ++k) {
        TOLERANCE_WHILE(k <= degree - r) {
          PRECISE vec4 x = om1 * row.c[k] + t1 * row.c[k + 1];
          row.c[k] = x;
        }
      }
      left[r] = row.c[0];
    }
  }
  PRECISE float s = t0 / t1;
  PRECISE float om = 1.0f - s;
  TOLERANCE_UNROLL for (int k = 0; k < TOLERANCE_ROW_ORDER; ++k) {
    TOLERANCE_WHILE(k <= degree) row.c[k] = left[k];
  }
  vec4 right[TOLERANCE_ROW_ORDER];
  right[degree] = row.c[degree];
  TOLERANCE_UNROLL for (int r = 1; r < TOLERANCE_ROW_ORDER; ++r) {
    TOLERANCE_WHILE(r <= degree) {
      TOLERANCE_UNROLL for (int k = 0; k < TOLERANCE_ROW_ORDER - 1; ++k) {
        TOLERANCE_WHILE(k <= degree - r) {
          PRECISE vec4 x = om * row.c[k] + s * row.c[k + 1];
          row.c[k] = x;
        }
      }
      right[degree - r] = row.c[degree - r];
    }
  }
  TOLERANCE_UNROLL for (int k = 0; k < TOLERANCE_ROW_ORDER; ++k) {
    TOLERANCE_WHILE(k <= degree) row.c[k] = right[k];
  }
}

// ‖v‖, scaled by its largest |component| first so that the squares neither underflow nor
// overflow (coordinates of 10⁻³⁰ or 10³⁰ keep their bound) and a scale by 2ᵏ scales it exactly.
// 0 or not finite: `big` itself, picked by selects rather than an early return: each bicubic
// rule T shader inlines dozens of norms, and their branches cost lavapipe's compiler ~1.5 ms a
// shader at every run (of ~9).
float toleranceNorm(vec3 v) {
  PRECISE float big = max(abs(v.x), max(abs(v.y), abs(v.z)));
  bool positive = big > 0.0f;
  bool bounded = big <= 3.0e38f;  // false for ∞ and NaN
  float divisor = positive ? big : 1.0f;
  divisor = bounded ? divisor : 1.0f;
  PRECISE vec3 w = v / divisor;
  PRECISE float r = big * sqrt(dot(w, w));
  r = positive ? r : big;
  r = bounded ? r : big;
  return r;
}

float maxAbsComponent(vec3 p) { return max(abs(p.x), max(abs(p.y), abs(p.z))); }

// The node's midpoint along one parameter.
float toleranceMidpoint(float lo, float hi) {
  PRECISE float r = lo + (hi - lo) * 0.5f;
  return r;
}

// (c − b) − (b − a), the first differences' largest |component| raised into big1.
vec3 secondDifferenceOf(vec3 a, vec3 b, vec3 c, INOUT(float) big1) {
  PRECISE vec3 x = c - b;
  PRECISE vec3 y = b - a;
  big1 = max(big1, max(maxAbsComponent(x), maxAbsComponent(y)));
  PRECISE vec3 d = x - y;
  return d;
}

// (d − c) − (b − a) for a = P_ij, b = P_i+1,j, c = P_i,j+1, d = P_i+1,j+1, likewise.
vec3 twistOf(vec3 a, vec3 b, vec3 c, vec3 d, INOUT(float) big1) {
  PRECISE vec3 x = d - c;
  PRECISE vec3 y = b - a;
  big1 = max(big1, max(maxAbsComponent(x), maxAbsComponent(y)));
  PRECISE vec3 t = x - y;
  return t;
}

// Per coordinate, the restricted difference net of degrees d_u × d_v is within
// u·(2·F₁ + (1 + 6·(d_u + d_v))·F₂) of the exact one (u = 2⁻²⁴): the differences' own
// rounding, then ≤ 2d lerps a direction, each within 3u·F₂ (docs/quadtree.md, "fp32").
float differenceNetError(float big1, float big2, int du, int dv) {
  PRECISE float lerps = float(1 + 6 * (du + dv));
  PRECISE float twice = 2.0f * big1;
  PRECISE float e = twice + lerps * big2;
  return e;
}

// One restricted second-difference net's summary: the largest norm of its entries, the
// centre of their bounding box and their largest distance from it (two passes over the
// entries: netTermsInclude, then netTermsSpread after netTermsCentre).
struct NetTerms {
  vec3 lo;
  vec3 hi;
  vec3 centre;
  float largest;
  float spread;
};

NetTerms emptyNetTerms() {
  NetTerms t;
  t.lo = vec3(3.0e38f);
  t.hi = vec3(-3.0e38f);
  t.centre = vec3(0.0f);
  t.largest = 0.0f;
  t.spread = 0.0f;
  return t;
}

void netTermsInclude(INOUT(NetTerms) t, vec3 v) {
  t.lo = min(t.lo, v);
  t.hi = max(t.hi, v);
  t.largest = max(t.largest, toleranceNorm(v));
}

void netTermsCentre(INOUT(NetTerms) t) {
  PRECISE vec3 halfWidth = (t.hi - t.lo) * 0.5f;
  PRECISE vec3 c = t.lo + halfWidth;
  t.centre = t.largest > 0.0f ? c : vec3(0.0f);
}

void netTermsSpread(INOUT(NetTerms) t, vec3 v) {
  PRECISE vec3 d = v - t.centre;
  t.spread = max(t.spread, toleranceNorm(d));
}

// Rule T's terms of one node, in node-local units (s, t) ∈ [0,1]²: `bounds` = (M_ss, M_st,
// M_tt, guard), the largest norms of the second derivatives' nets and the fp32 guard (the
// bound (M_ss + 2·M_st + M_tt)/8); ss, st, tt = constant second derivatives C of a quadratic
// and `spread` = (m_ss, m_st, m_tt) the largest distances of the nets from them (the bound
// (W(C) + m_ss + 2·m_st + m_tt)/8, toleranceBoundNumerator); spread.w = the share of m that the
// grid estimate counts, kToleranceSpreadShare for difference nets. Nets without centres
// (rational, the revolution bound) have C = 0, m = M and a share of 1: a child's terms shrink
// by 1/k² at best, with no spread about centres of its own to lose.
struct ToleranceTerms {
  vec4 bounds;
  vec4 spread;
  vec4 ss;
  vec4 st;
  vec4 tt;
};

ToleranceTerms toleranceTermsOf(vec4 bounds) {
  ToleranceTerms t;
  t.bounds = bounds;
  t.spread = vec4(vec3(bounds), 1.0f);
  t.ss = vec4(0.0f);
  t.st = vec4(0.0f);
  t.tt = vec4(0.0f);
  return t;
}

// The node's terms from its three restricted difference nets (in the patch's parameters) and
// their error terms: M_ss = n(n−1)·h_u²·‖Δ²_s‖, M_st = n·m·h_u·h_v·‖Δ_sΔ_t‖, M_tt =
// m(m−1)·h_v²·‖Δ²_t‖ — de Casteljau commutes with differencing, so these are the node-local
// bounds of the restricted net — and likewise C and m from the nets' centres and spreads.
ToleranceTerms differenceTerms(IN(NetTerms) ss, IN(NetTerms) st, IN(NetTerms) tt, vec3 errors,
                               int n, int m, vec4 rect) {
  PRECISE float hu = rect.z - rect.x;
  PRECISE float hv = rect.w - rect.y;
  PRECISE float css = float(n * (n - 1)) * (hu * hu);
  PRECISE float cst = float(n * m) * (hu * hv);
  PRECISE float ctt = float(m * (m - 1)) * (hv * hv);
  PRECISE float mss = css * ss.largest;
  PRECISE float mst = cst * st.largest;
  PRECISE float mtt = ctt * tt.largest;
  PRECISE float twoSt = 2.0f * cst;
  PRECISE float spread = (css * errors.x + twoSt * errors.y) + ctt * errors.z;
  PRECISE float guard = kToleranceDifferenceGuard * spread;
  ToleranceTerms t;
  t.bounds = vec4(mss, mst, mtt, guard);
  PRECISE float sss = css * ss.spread;
  PRECISE float sst = cst * st.spread;
  PRECISE float stt = ctt * tt.spread;
  t.spread = vec4(sss, sst, stt, kToleranceSpreadShare);
  PRECISE vec3 css3 = css * ss.centre;
  PRECISE vec3 cst3 = cst * st.centre;
  PRECISE vec3 ctt3 = ctt * tt.centre;
  t.ss = vec4(css3, 0.0f);
  t.st = vec4(cst3, 0.0f);
  t.tt = vec4(ctt3, 0.0f);
  return t;
}

// A bicubic difference net, at most 4 × 4 entries, entry (i, j) at i·4 + j (xyz; w = 0).
struct DifferenceNet4 {
  vec4 c[16];
};

// Restricts the net's lines to [t0, t1]: lines 0..lines−1 of degree+1 entries each, entry e of
// line l at q.c[l·lineStride + e·entryStride] (the columns along u: strides 1 and 4; the rows
// along v: 4 and 1).
void restrictNetLines(INOUT(DifferenceNet4) q, int lines, int degree, int lineStride,
                      int entryStride, float t0, float t1) {
  BernsteinRow4 row;
  TOLERANCE_UNROLL for (int l = 0; l < 4; ++l) {
    if (l < lines) {
      TOLERANCE_UNROLL for (int e = 0; e < 4; ++e)
        if (e <= degree) row.c[e] = q.c[l * lineStride + e * entryStride];
      restrictBernsteinRow(row, degree, t0, t1);
      TOLERANCE_UNROLL for (int e = 0; e < 4; ++e)
        if (e <= degree) q.c[l * lineStride + e * entryStride] = row.c[e];
    }
  }
}

// The (du + 1) × (dv + 1) net restricted to rect (de Casteljau along u, then v); its terms.
NetTerms restrictedNetTerms(INOUT(DifferenceNet4) q, int du, int dv, vec4 rect) {
  if (rect.x != 0.0f || rect.z != 1.0f) restrictNetLines(q, dv + 1, du, 1, 4, rect.x, rect.z);
  if (rect.y != 0.0f || rect.w != 1.0f) restrictNetLines(q, du + 1, dv, 4, 1, rect.y, rect.w);
  NetTerms t = emptyNetTerms();
  TOLERANCE_UNROLL for (int i = 0; i < 4; ++i)
    TOLERANCE_UNROLL for (int j = 0; j < 4; ++j)
      if (i <= du && j <= dv) netTermsInclude(t, vec3(q.c[i * 4 + j]));
  netTermsCentre(t);
  TOLERANCE_UNROLL for (int i = 0; i < 4; ++i)
    TOLERANCE_UNROLL for (int j = 0; j < 4; ++j)
      if (i <= du && j <= dv) netTermsSpread(t, vec3(q.c[i * 4 + j]));
  return t;
}

// The terms of one of the bicubic patch's three second-difference nets restricted to the
// node (net 0 = Δ²_s (2 × 4), 1 = Δ_sΔ_t (3 × 3), 2 = Δ²_t (4 × 2)), and its error term of
// differenceNetError in `error`. Differences of control points: the same for the model moved
// anywhere fp32 holds it exactly (docs/quadtree.md, "fp32"). One function a net, so that a
// shader may compute some nets and another shader the rest (quadtree_tolerance_nets.comp.glsl).
NetTerms bicubicNetBound(IN(BicubicPatch) bp, vec4 rect, int net, OUT(float) error) {
  DifferenceNet4 q;
  PRECISE float big1 = 0.0f;
  PRECISE float big2 = 0.0f;
  if (net == 0) {
    TOLERANCE_UNROLL for (int i = 0; i < 2; ++i)
      TOLERANCE_UNROLL for (int j = 0; j < 4; ++j) {
        vec3 d = secondDifferenceOf(vec3(bp.cp[i * 4 + j]), vec3(bp.cp[(i + 1) * 4 + j]),
                                    vec3(bp.cp[(i + 2) * 4 + j]), big1);
        big2 = max(big2, maxAbsComponent(d));
        q.c[i * 4 + j] = vec4(d, 0.0f);
      }
    error = differenceNetError(big1, big2, 1, 3);
    return restrictedNetTerms(q, 1, 3, rect);
  }
  if (net == 1) {
    TOLERANCE_UNROLL for (int i = 0; i < 3; ++i)
      TOLERANCE_UNROLL for (int j = 0; j < 3; ++j) {
        vec3 d = twistOf(vec3(bp.cp[i * 4 + j]), vec3(bp.cp[(i + 1) * 4 + j]),
                         vec3(bp.cp[i * 4 + j + 1]), vec3(bp.cp[(i + 1) * 4 + j + 1]), big1);
        big2 = max(big2, maxAbsComponent(d));
        q.c[i * 4 + j] = vec4(d, 0.0f);
      }
    error = differenceNetError(big1, big2, 2, 2);
    return restrictedNetTerms(q, 2, 2, rect);
  }
  TOLERANCE_UNROLL for (int i = 0; i < 4; ++i)
    TOLERANCE_UNROLL for (int j = 0; j < 2; ++j) {
      vec3 d = secondDifferenceOf(vec3(bp.cp[i * 4 + j]), vec3(bp.cp[i * 4 + j + 1]),
                                  vec3(bp.cp[i * 4 + j + 2]), big1);
      big2 = max(big2, maxAbsComponent(d));
      q.c[i * 4 + j] = vec4(d, 0.0f);
    }
  error = differenceNetError(big1, big2, 3, 1);
  return restrictedNetTerms(q, 3, 1, rect);
}

// The bicubic patch's terms on the node from its three nets' terms and error terms.
ToleranceTerms bicubicTermsOfNets(IN(NetTerms) ss, IN(NetTerms) st, IN(NetTerms) tt,
                                  vec3 errors, vec4 rect) {
  return differenceTerms(ss, st, tt, errors, 3, 3, rect);
}

// One net's terms as the first of rule T's two dispatches passes them to the second
// (ToleranceNetBounds, shaders/layout.h): (centre, spread), and the largest norm apart. Stored
// floats as they are, so the second dispatch computes as bicubicSecondBounds does.
vec4 netCentreSpread(IN(NetTerms) t) {
  return vec4(t.centre, t.spread);
}

NetTerms netTermsOf(vec4 centreSpread, float largest) {
  NetTerms t = emptyNetTerms();
  t.centre = vec3(centreSpread);
  t.spread = centreSpread.w;
  t.largest = largest;
  return t;
}

// The terms of the bicubic patch on the node: its three second-difference nets restricted to
// the node.
ToleranceTerms bicubicSecondBounds(IN(BicubicPatch) bp, vec4 rect) {
  vec3 errors;
  NetTerms ss = bicubicNetBound(bp, rect, 0, errors.x);
  NetTerms st = bicubicNetBound(bp, rect, 1, errors.y);
  NetTerms tt = bicubicNetBound(bp, rect, 2, errors.z);
  return bicubicTermsOfNets(ss, st, tt, errors, rect);
}

// The bound's absolute guard for the centred form, as a fraction of (M_ss + 2·M_st + M_tt):
// C's products and W's sums round by a few u relative to the M's, not to the result, which
// may cancel (docs/quadtree.md, "A tighter bound").
const float kToleranceCentredGuard = 3.814697265625e-6f;  // 2⁻¹⁸

// W(C) = max over |τ| ≤ 1 of ‖C_ss + 2τ·C_st + τ²·C_tt‖ and ‖τ²·C_ss + 2τ·C_st + C_tt‖, bounded
// by the two curves' Bézier control points on τ ∈ [−1, 0] and [0, 1]: C_ss ± 2·C_st + C_tt
// (τ = ±1), C_ss ± C_st and C_tt ± C_st (the middle ones; C_ss and C_tt at τ = 0 are their
// means). 8 × the largest deviation of any triangle in the node from a quadratic surface of
// constant second derivatives C (docs/quadtree.md, "A tighter bound").
float quadraticPartBound(vec3 ss, vec3 st, vec3 tt) {
  PRECISE vec3 sum = ss + tt;
  PRECISE vec3 twoSt = 2.0f * st;
  PRECISE vec3 p = sum + twoSt;
  PRECISE vec3 q = sum - twoSt;
  PRECISE vec3 sp = ss + st;
  PRECISE vec3 sm = ss - st;
  PRECISE vec3 tp = tt + st;
  PRECISE vec3 tm = tt - st;
  PRECISE float w = max(toleranceNorm(p), toleranceNorm(q));
  w = max(w, max(toleranceNorm(sp), toleranceNorm(sm)));
  w = max(w, max(toleranceNorm(tp), toleranceNorm(tm)));
  return w;
}

// W₁(C), the same for triangles whose edges all have d_s·d_t ≥ 0 (they keep to the diagonal
// (0,0)–(1,1): Σ_st ≥ 0): max over τ ∈ [0, 1] of the two curves, by their control points
// C_ss, C_ss + C_st, C_ss + 2·C_st + C_tt and C_tt, C_tt + C_st, and ‖C_ss + C_tt‖ (the
// corner Σ = diag(¼, ¼) of that set). With −C_st: the other diagonal's W₂ (docs/quadtree.md,
// "One diagonal"). Both are at most W(C).
float diagonalQuadraticPartBound(vec3 ss, vec3 st, vec3 tt) {
  PRECISE vec3 sum = ss + tt;
  PRECISE vec3 twoSt = 2.0f * st;
  PRECISE vec3 p = sum + twoSt;
  PRECISE vec3 sp = ss + st;
  PRECISE vec3 tp = tt + st;
  PRECISE float w = max(toleranceNorm(p), toleranceNorm(sum));
  w = max(w, max(toleranceNorm(sp), toleranceNorm(tp)));
  w = max(w, max(toleranceNorm(ss), toleranceNorm(tt)));
  return w;
}

// The smaller of W₁ and W₂ (the better diagonal), and in `diagonal` which
// (kToleranceMainDiagonal on ties).
float betterDiagonalBound(vec3 ss, vec3 st, vec3 tt, OUT(uint) diagonal) {
  float mainW = diagonalQuadraticPartBound(ss, st, tt);
  PRECISE vec3 negated = -st;
  float antiW = diagonalQuadraticPartBound(ss, negated, tt);
  diagonal = antiW < mainW ? kToleranceAntiDiagonal : kToleranceMainDiagonal;
  return antiW < mainW ? antiW : mainW;
}

// 8·k_u²·k_v² × the bound, before its guards, of a child of the node split k_u × k_v (uu =
// k_u², uv = k_u·k_v, vv = k_v²): the smaller of (M_ss·k_v² + 2·M_st·k_u·k_v + M_tt·k_u²) —
// every term scales by 1/k² in the child — and the centred form W(C_ss·k_v², C_st·k_u·k_v,
// C_tt·k_u²) + spreadShare·(m_ss·k_v² + 2·m_st·k_u·k_v + m_tt·k_u²) + its absolute guard (W
// is homogeneous of degree 1). spreadShare = 1 is the sound estimate; the grid split takes
// the terms' own share (spread.w).
// knownW ≥ 0: that W, the node's own where C = 0 (toleranceGridCounts), else W is computed.
float toleranceGridNumerator(IN(ToleranceTerms) t, float uu, float uv, float vv, float spreadShare,
                             float knownW) {
  PRECISE float twoSt = 2.0f * t.bounds.y;
  PRECISE float plain = (t.bounds.x * vv + twoSt * uv) + t.bounds.z * uu;
  PRECISE float w = knownW;
  if (!(knownW >= 0.0f)) {
    PRECISE vec3 ss = vv * vec3(t.ss);
    PRECISE vec3 st = uv * vec3(t.st);
    PRECISE vec3 tt = uu * vec3(t.tt);
    uint diagonal;
    w = betterDiagonalBound(ss, st, tt, diagonal);
  }
  PRECISE float twoSpreadSt = 2.0f * t.spread.y;
  PRECISE float rest = (t.spread.x * vv + twoSpreadSt * uv) + t.spread.z * uu;
  PRECISE float guard = plain * kToleranceCentredGuard;
  PRECISE float counted = rest * spreadShare;
  PRECISE float centred = (w + counted) + guard;
  return centred < plain ? centred : plain;  // not min(): the same pick for a NaN on GPU and CPU
}

// Rule T's equal split of a node that fails δ: the fewest children k_u·k_v (each count at
// most the cap) whose estimated bound (1 + 2⁻¹⁰)·toleranceGridNumerator/(8·k_u²·k_v²) + guard
// is within δ, as k_u | k_v << 8; 0 when no counts within the cap reach δ. Restricting a
// polynomial net to 1/k of the interval scales its second differences by 1/k² and keeps them
// convex combinations of the parent's (so within the parent's spreads of its centres, scaled
// alike): for polynomial patches the children's own bounds are at most this estimate, up to
// rounding; rational children just split again where it was optimistic. Compared multiplied
// out by k_u²·k_v² (no division: GPU and mirror agree bit for bit); among equal counts, the
// smaller estimate.
// `nodeW`: the better diagonal's W of the node's own C (toleranceDecision's wDiagonal).
uint toleranceGridCounts(IN(ToleranceTerms) t, float tolerance, uint cap, float nodeW) {
  PRECISE float room = tolerance - t.bounds.w;
#ifdef __cplusplus
  // The mirrors' shortcut, the same bits: where C = 0 (rational nets, the revolution bound:
  // no centres) every k_u × k_v scales it to itself (±0 times a positive count, signs kept),
  // so each W is the node's. The shaders keep the one path: no branch for lavapipe to compile.
  bool centreless = t.ss.x == 0.0f && t.ss.y == 0.0f && t.ss.z == 0.0f && t.st.x == 0.0f &&
                    t.st.y == 0.0f && t.st.z == 0.0f && t.tt.x == 0.0f && t.tt.y == 0.0f &&
                    t.tt.z == 0.0f;
  float knownW = centreless ? nodeW : -1.0f;
#else
  float knownW = -1.0f;
#endif
  uint best = 0u;
  uint bestCount = cap * cap + 1u;
  PRECISE float bestNum = 0.0f;
  PRECISE float bestDen = 1.0f;
  for (uint ku = 1u; ku <= kToleranceSplitCapMax; ++ku) {
    if (ku > cap) break;
    for (uint kv = 1u; kv <= kToleranceSplitCapMax; ++kv) {
      if (kv > cap || ku * kv > bestCount) break;
      if (ku * kv < 2u) continue;
      PRECISE float fu = float(ku);
      PRECISE float fv = float(kv);
      PRECISE float uu = fu * fu;
      PRECISE float vv = fv * fv;
      PRECISE float uv = fu * fv;
      PRECISE float num = toleranceGridNumerator(t, uu, uv, vv, t.spread.w, knownW);
      PRECISE float scaled = num * 0.125f;
      PRECISE float guarded = scaled * kToleranceRelativeGuard;
      PRECISE float den = uu * vv;
      PRECISE float allowed = room * den;
      if (!(guarded <= allowed)) continue;
      PRECISE float lhs = num * bestDen;
      PRECISE float rhs = bestNum * den;
      if (ku * kv < bestCount || lhs < rhs) {
        best = ku | (kv << 8u);
        bestCount = ku * kv;
        bestNum = num;
        bestDen = den;
      }
      break;  // a larger k_v only adds children
    }
  }
  return best;
}

// The node's guarded bound from the centred form's W (W(C), or one diagonal's), its spread
// term and absolute guard, and the plain sum M_ss + 2·M_st + M_tt: the smaller form, /8, times
// 1 + 2⁻¹⁰, plus the coordinates' guard.
float toleranceGuardedBound(float w, float rest, float guard, float sum, float coordinateGuard) {
  PRECISE float centred = (w + rest) + guard;
  PRECISE float tighter = centred < sum ? centred : sum;
  PRECISE float scaled = tighter * 0.125f;
  PRECISE float guarded = scaled * kToleranceRelativeGuard;
  PRECISE float bound = guarded + coordinateGuard;
  return bound;
}

// The decision of rule T from the node's terms. Every triangle with its corners in the leaf
// (its two triangles, its ring's triangles, a fan) is within both (A + B)/8, A = M_ss + M_st
// and B = M_tt + M_st, and (W(C) + m_ss + 2·m_st + m_tt)/8 of the surface (docs/quadtree.md);
// the bound is the smaller, guarded; smaller again, with W₁ or W₂ for W, for triangles that
// keep to one diagonal: the node's bound is that one where it is smaller, and a leaf then
// names the diagonal in `pad` for the triangulator. Not within δ: k_u × k_v equal children where counts
// within the cap reach δ (toleranceGridCounts); else split at the midpoint along u where
// A ≥ B/2, v where B ≥ A/2 (both when neither holds: a NaN bound).
NodeDecision toleranceDecision(IN(ToleranceTerms) t, IN(QuadNode) node, IN(ClassifyPush) params) {
  vec4 r = node.rect;
  PRECISE float a = t.bounds.x + t.bounds.y;
  PRECISE float b = t.bounds.z + t.bounds.y;
  PRECISE float sum = a + b;
#ifdef TOLERANCE_DECISION_CENTRELESS_SHORTCUT
  // A C++ includer's shortcut, the same bits: where C = 0 (the revolution bound's terms) every
  // norm W takes is of a ±0 vector, +0, so W = W₁ = W₂ = +0 and the main diagonal wins the
  // tie; the twenty norms were most of the revolution bound's decision. (Only where asked: in
  // the rule T variants' units the branch changed the compiler's inlining, and cost more.)
  bool centreless = t.ss.x == 0.0f && t.ss.y == 0.0f && t.ss.z == 0.0f && t.st.x == 0.0f &&
                    t.st.y == 0.0f && t.st.z == 0.0f && t.tt.x == 0.0f && t.tt.y == 0.0f &&
                    t.tt.z == 0.0f;
  PRECISE float w = 0.0f;
  uint diagonal = kToleranceMainDiagonal;
  PRECISE float wDiagonal = 0.0f;
  if (!centreless) {
    w = quadraticPartBound(vec3(t.ss), vec3(t.st), vec3(t.tt));
    wDiagonal = betterDiagonalBound(vec3(t.ss), vec3(t.st), vec3(t.tt), diagonal);
  }
#else
  PRECISE float w = quadraticPartBound(vec3(t.ss), vec3(t.st), vec3(t.tt));
  uint diagonal;
  PRECISE float wDiagonal = betterDiagonalBound(vec3(t.ss), vec3(t.st), vec3(t.tt), diagonal);
#endif
  PRECISE float twoSpreadSt = 2.0f * t.spread.y;
  PRECISE float rest = (t.spread.x + twoSpreadSt) + t.spread.z;
  PRECISE float guard = sum * kToleranceCentredGuard;
  PRECISE float bound = toleranceGuardedBound(w, rest, guard, sum, t.bounds.w);
  PRECISE float boundDiagonal = toleranceGuardedBound(wDiagonal, rest, guard, sum, t.bounds.w);
  float us = toleranceMidpoint(r.x, r.z);
  float vs = toleranceMidpoint(r.y, r.w);
  PRECISE float share = sum > 0.0f ? a / sum : 0.5f;
  NodeDecision d;
  d.split = vec4(us, vs, 0.0f, 0.0f);
  d.linearity = share;
  // The node's bound: the better diagonal's where it is smaller (the leaf's triangles then keep
  // to that diagonal), else the one for any triangles.
  bool oneDiagonal = boundDiagonal < bound;
  d.flatness = oneDiagonal ? boundDiagonal : bound;
  d.pad = 0u;
  if (d.flatness <= params.tolerance) {
    d.cause = kCauseWithinTolerance;
    d.pad = oneDiagonal ? diagonal : kToleranceAnyDiagonal;
  } else if (node.level >= params.maxDepth) {
    d.cause = kCauseMaxDepth;
  } else if (min(r.z - r.x, r.w - r.y) < params.minSize) {
    d.cause = kCauseMinSize;
  } else {
    uint grid = toleranceGridCounts(t, params.tolerance, params.toleranceSplitCap, wDiagonal);
    PRECISE float halfA = 0.5f * a;
    PRECISE float halfB = 0.5f * b;
    bool splitU = !(a < halfB);
    bool splitV = !(b < halfA);
    if (grid != 0u) {
      d.cause = kCauseSplitGrid;
      d.pad = grid;
    } else if (splitU && !splitV) {
      d.cause = kCauseSplitU;
    } else if (splitV && !splitU) {
      d.cause = kCauseSplitV;
    } else {
      d.cause = kCauseSplit;
    }
  }
  return d;
}

#endif
