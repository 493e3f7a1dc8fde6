// Rule T's second-derivative bounds for general patches (degree 1..7, polynomial or rational)
// in the gNet arrays of lib/division_count.h, in fp32: sup‖S_ss‖, sup‖S_st‖, sup‖S_tt‖ in
// node-local coordinates — for a polynomial net, its second-difference nets restricted to the
// node (no absolute coordinate enters); for a rational one, the homogeneous net moved to its
// control point of largest weight, restricted, then the `split` method (B1..B8 over the weight ratios,
// docs/rational_division.md). At namespace scope; include
// shared_glsl_cpp.h, layout.h, division_count.h and tolerance_bound.h first.
#ifndef TESSERA_TOLERANCE_NET_H
#define TESSERA_TOLERANCE_NET_H

// Restricts `count` rows of gNet.h to [t0, t1] (de Casteljau), in place: entry k of row r is
// at r·rowStride + k·entryStride, `degree` + 1 entries a row.
void restrictDivisionNetRows(int count, int degree, int rowStride, int entryStride, float t0,
                             float t1) {
  BernsteinRow4 row;
  for (int r = 0; r < kGeneralMaxOrder; ++r) {
    if (r >= count) break;
    for (int k = 0; k < kGeneralMaxOrder; ++k) {
      if (k > degree) break;
      row.c[k] = gNet.h[r * rowStride + k * entryStride];
    }
    restrictBernsteinRow(row, degree, t0, t1);
    for (int k = 0; k < kGeneralMaxOrder; ++k) {
      if (k > degree) break;
      gNet.h[r * rowStride + k * entryStride] = row.c[k];
    }
  }
}

// gNet.h restricted to rect = (u0, v0, u1, v1) and reparametrised to [0,1]², in place: along u
// (the m + 1 columns j, entries i at i·(m+1) + j), then along v (the n + 1 rows i).
void restrictDivisionNet(vec4 rect) {
  int n = DIVISION_NET_N;
  int m = DIVISION_NET_M;
  if (rect.x != 0.0f || rect.z != 1.0f) restrictDivisionNetRows(m + 1, n, 1, m + 1, rect.x, rect.z);
  if (rect.y != 0.0f || rect.w != 1.0f) restrictDivisionNetRows(n + 1, m, m + 1, 1, rect.y, rect.w);
}

// Difference net `kind` (0: Δ²_s, 1: Δ_sΔ_t, 2: Δ²_t) of the control points in gNet.d1u
// (the polynomial path's copy of the net, (n + 1) × (m + 1)) into gNet.h, entry (i, j) at
// i·(dv + 1) + j for its degrees du × dv, restricted to rect; returns its terms, and its
// error term of differenceNetError in `error`.
NetTerms restrictedDifferenceNet(int kind, vec4 rect, OUT(float) error) {
  int n = DIVISION_NET_N;
  int m = DIVISION_NET_M;
  int s = m + 1;
  int du = kind == 0 ? n - 2 : (kind == 1 ? n - 1 : n);
  int dv = kind == 0 ? m : (kind == 1 ? m - 1 : m - 2);
  error = 0.0f;
  if (du < 0 || dv < 0) return emptyNetTerms();
  PRECISE float big1 = 0.0f;
  PRECISE float big2 = 0.0f;
  for (int i = 0; i < kGeneralMaxOrder; ++i) {
    if (i > du) break;
    for (int j = 0; j < kGeneralMaxOrder; ++j) {
      if (j > dv) break;
      vec3 a = vec3(gNet.d1u[i * s + j]);
      vec3 d;
      if (kind == 0) {
        d = secondDifferenceOf(a, vec3(gNet.d1u[(i + 1) * s + j]),
                               vec3(gNet.d1u[(i + 2) * s + j]), big1);
      } else if (kind == 1) {
        d = twistOf(a, vec3(gNet.d1u[(i + 1) * s + j]), vec3(gNet.d1u[i * s + j + 1]),
                    vec3(gNet.d1u[(i + 1) * s + j + 1]), big1);
      } else {
        d = secondDifferenceOf(a, vec3(gNet.d1u[i * s + j + 1]), vec3(gNet.d1u[i * s + j + 2]),
                               big1);
      }
      big2 = max(big2, maxAbsComponent(d));
      gNet.h[i * (dv + 1) + j] = vec4(d, 0.0f);
    }
  }
  if (rect.x != 0.0f || rect.z != 1.0f)
    restrictDivisionNetRows(dv + 1, du, 1, dv + 1, rect.x, rect.z);
  if (rect.y != 0.0f || rect.w != 1.0f)
    restrictDivisionNetRows(du + 1, dv, dv + 1, 1, rect.y, rect.w);
  NetTerms t = emptyNetTerms();
  for (int k = 0; k < kGeneralMaxOrder * kGeneralMaxOrder; ++k) {
    if (k >= (du + 1) * (dv + 1)) break;
    netTermsInclude(t, vec3(gNet.h[k]));
  }
  netTermsCentre(t);
  for (int k = 0; k < kGeneralMaxOrder * kGeneralMaxOrder; ++k) {
    if (k >= (du + 1) * (dv + 1)) break;
    netTermsSpread(t, vec3(gNet.h[k]));
  }
  error = differenceNetError(big1, big2, du, dv);
  return t;
}

// The terms of the polynomial net in gNet.d1u on rect: the three second-difference nets
// restricted to the node (differenceTerms in tolerance_bound.h).
ToleranceTerms polynomialNetSecondBounds(vec4 rect) {
  vec3 errors;
  NetTerms ss = restrictedDifferenceNet(0, rect, errors.x);
  NetTerms st = restrictedDifferenceNet(1, rect, errors.y);
  NetTerms tt = restrictedDifferenceNet(2, rect, errors.z);
  return differenceTerms(ss, st, tt, errors, DIVISION_NET_N, DIVISION_NET_M, rect);
}

// (M_ss, M_st, M_tt, guard) of the rational net in gNet.h (translated to its control point of
// largest weight, then restricted to the node): the `split` method's a, b, c (what divisionCounts
// passes to divisionRealCounts), b = min(S_st, S_ts bounds); the guard from the largest |x/w|
// of the points of positive weight, in that local frame. A heuristic, not a proof: the
// split method's products and quotients of fp32 coordinates are not analysed (the tests
// check it against the double reference). Every M is kToleranceUnbounded when the
// weight ratios fail (w may vanish on the node).
vec4 rationalNetSecondBounds() {
  int count = (DIVISION_NET_N + 1) * (DIVISION_NET_M + 1);
  bool anyVanished = false;
  bool anyNegative = false;
  PRECISE float big = 0.0f;
  for (int k = 0; k < count; ++k) {
    vec4 h = gNet.h[k];
    anyVanished = anyVanished || h.w == 0.0f;
    anyNegative = anyNegative || h.w < 0.0f;
    if (h.w > 0.0f) {
      PRECISE vec3 p = vec3(h) / h.w;
      big = max(big, maxAbsComponent(p));
    }
  }
  vec2 ratios = vec2(0.0f, 1.0f);
  if (anyVanished || anyNegative) {
    if (!divisionWeightRatios(kToleranceRatioPieces, ratios))
      return vec4(kToleranceUnbounded, kToleranceUnbounded, kToleranceUnbounded, 0.0f);
  }
  divisionDerivativeNets();
  divisionClassMaxima();
  PRECISE float mss = divisionCombine(0, ratios.x, ratios.y);
  PRECISE float mst = min(divisionCombine(1, ratios.x, ratios.y),
                          divisionCombine(3, ratios.x, ratios.y));
  PRECISE float mtt = divisionCombine(2, ratios.x, ratios.y);
  int n = DIVISION_NET_N;
  int m = DIVISION_NET_M;
  PRECISE float guard = kToleranceRoundingGuard * float(n * n + m * m) * big;
  return vec4(mss, mst, mtt, guard);
}

#endif
