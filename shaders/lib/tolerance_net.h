// Rule T's second-derivative bounds for general patches (degree 1..7, polynomial or rational)
// on the homogeneous net in gNet.h of lib/division_count.h, in fp32: restrict it to the node,
// then bound sup‖S_ss‖, sup‖S_st‖, sup‖S_tt‖ in node-local coordinates — by the second
// differences for a polynomial net, by the `split` method (B1..B8 over the weight ratios,
// docs/rational_division.md) for a rational one. At namespace scope; include
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
  int n = gNet.n;
  int m = gNet.m;
  if (rect.x != 0.0f || rect.z != 1.0f) restrictDivisionNetRows(m + 1, n, 1, m + 1, rect.x, rect.z);
  if (rect.y != 0.0f || rect.w != 1.0f) restrictDivisionNetRows(n + 1, m, m + 1, 1, rect.y, rect.w);
}

// (M_ss, M_st, M_tt) of the polynomial net in gNet.h: n(n−1)·max‖Δ²_s P‖, n·m·max‖Δ_sΔ_t P‖,
// m(m−1)·max‖Δ²_t P‖, and the rounding guard 2⁻²⁰·(n² + m²)·max|P|.
vec4 polynomialNetSecondBounds() {
  int n = gNet.n;
  int m = gNet.m;
  int s = m + 1;
  PRECISE float dss = 0.0f;
  PRECISE float dst = 0.0f;
  PRECISE float dtt = 0.0f;
  PRECISE float big = 0.0f;
  for (int i = 0; i < kGeneralMaxOrder; ++i) {
    if (i > n) break;
    for (int j = 0; j < kGeneralMaxOrder; ++j) {
      if (j > m) break;
      vec3 p = vec3(gNet.h[i * s + j]);
      big = max(big, maxAbsComponent(p));
      if (i + 2 <= n)
        dss = max(dss, secondDifferenceNorm(p, vec3(gNet.h[(i + 1) * s + j]),
                                            vec3(gNet.h[(i + 2) * s + j])));
      if (j + 2 <= m)
        dtt = max(dtt, secondDifferenceNorm(p, vec3(gNet.h[i * s + j + 1]),
                                            vec3(gNet.h[i * s + j + 2])));
      if (i < n && j < m)
        dst = max(dst, twistNorm(p, vec3(gNet.h[(i + 1) * s + j]), vec3(gNet.h[i * s + j + 1]),
                                 vec3(gNet.h[(i + 1) * s + j + 1])));
    }
  }
  PRECISE float mss = float(n * (n - 1)) * dss;
  PRECISE float mst = float(n * m) * dst;
  PRECISE float mtt = float(m * (m - 1)) * dtt;
  PRECISE float guard = kToleranceRoundingGuard * float(n * n + m * m) * big;
  return vec4(mss, mst, mtt, guard);
}

// (M_ss, M_st, M_tt, guard) of the rational net in gNet.h: the `split` method's a, b, c (what
// divisionCounts passes to divisionRealCounts), b = min(S_st, S_ts bounds); the guard from the
// largest |x/w| of the points of positive weight. Every M is kToleranceUnbounded when the
// weight ratios fail (w may vanish on the node).
vec4 rationalNetSecondBounds() {
  int count = (gNet.n + 1) * (gNet.m + 1);
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
  int n = gNet.n;
  int m = gNet.m;
  PRECISE float guard = kToleranceRoundingGuard * float(n * n + m * m) * big;
  return vec4(mss, mst, mtt, guard);
}

// The bounds of the net in gNet.h (already restricted to the node).
vec4 netSecondBounds(bool rational) {
  if (rational) return rationalNetSecondBounds();
  return polynomialNetSecondBounds();
}

#endif
