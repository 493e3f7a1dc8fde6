// Rule T (issue 15; docs/quadtree.md, "Rule T: tolerance") in fp32: the node's proven bound
// on the parametric deviation of every triangle it can emit, (M_ss + 2·M_st + M_tt)/8 from
// bounds M of the second derivatives in node-local coordinates (s, t) ∈ [0,1]², and the
// decision: leaf within δ, or split into k_u × k_v equal children (toleranceGridCounts), or
// along u, v or both at the node's midpoint.
// Compiled as GLSL (quadtree.comp.glsl, quadtree_general.comp.glsl) and as C++ (the mirrors)
// from this one text, at namespace scope. Include shared_glsl_cpp.h and layout.h first.
#ifndef TESSERA_TOLERANCE_BOUND_H
#define TESSERA_TOLERANCE_BOUND_H

// The fp32 bound is (1 + 2⁻¹⁰)·(M_ss + 2·M_st + M_tt)/8 + 2⁻²⁰·(n² + m²)·max|P|: the factor
// covers the rounding of the bound's own arithmetic, the term the rounding of the restricted
// net's coordinates (about 2·degree lerps per direction, each within an ulp of max|P|,
// amplified by the n(n−1) of the second differences).
const float kToleranceRelativeGuard = 1.0009765625f;  // 1 + 2⁻¹⁰
const float kToleranceRoundingGuard = 9.5367431640625e-7f;  // 2⁻²⁰
// A bound no δ accepts: where w may vanish on the node (rational nets the weight ratios
// cannot bound), the node splits in both directions.
const float kToleranceUnbounded = 1.0e30f;

// One row of Bernstein coefficients (at most kGeneralMaxOrder).
struct BernsteinRow4 {
  vec4 c[kGeneralMaxOrder];
};

// The row's coefficients restricted to [t0, t1] (0 ≤ t0 < t1 ≤ 1) and reparametrised to
// [0, 1]: split at t1 keeping the left piece, then at t0/t1 keeping the right piece (de
// Casteljau both times), as restrictCoefficients in host/geometry/homogeneous_net.h.
void restrictBernsteinRow(INOUT(BernsteinRow4) row, int degree, float t0, float t1) {
  vec4 left[kGeneralMaxOrder];
  left[0] = row.c[0];
  PRECISE float om1 = 1.0f - t1;
  for (int r = 1; r < kGeneralMaxOrder; ++r) {
    if (r > degree) break;
    for (int k = 0; k < kGeneralMaxOrder; ++k) {
      if (k > degree - r) break;
      PRECISE vec4 x = om1 * row.c[k] + t1 * row.c[k + 1];
      row.c[k] = x;
    }
    left[r] = row.c[0];
  }
  PRECISE float s = t0 / t1;
  PRECISE float om = 1.0f - s;
  for (int k = 0; k < kGeneralMaxOrder; ++k) {
    if (k > degree) break;
    row.c[k] = left[k];
  }
  vec4 right[kGeneralMaxOrder];
  right[degree] = row.c[degree];
  for (int r = 1; r < kGeneralMaxOrder; ++r) {
    if (r > degree) break;
    for (int k = 0; k < kGeneralMaxOrder; ++k) {
      if (k > degree - r) break;
      PRECISE vec4 x = om * row.c[k] + s * row.c[k + 1];
      row.c[k] = x;
    }
    right[degree - r] = row.c[degree - r];
  }
  for (int k = 0; k < kGeneralMaxOrder; ++k) {
    if (k > degree) break;
    row.c[k] = right[k];
  }
}

float toleranceNorm(vec3 v) {
  PRECISE float r = sqrt(dot(v, v));
  return r;
}

// ‖a − 2b + c‖ and ‖d − c − b + a‖ (a = P_ij, b = P_i+1,j, c = P_i,j+1, d = P_i+1,j+1).
float secondDifferenceNorm(vec3 a, vec3 b, vec3 c) {
  PRECISE vec3 d = (c - b) - (b - a);
  return toleranceNorm(d);
}

float twistNorm(vec3 a, vec3 b, vec3 c, vec3 d) {
  PRECISE vec3 t = (d - c) - (b - a);
  return toleranceNorm(t);
}

float maxAbsComponent(vec3 p) { return max(abs(p.x), max(abs(p.y), abs(p.z))); }

// The node's midpoint along one parameter.
float toleranceMidpoint(float lo, float hi) {
  PRECISE float r = lo + (hi - lo) * 0.5f;
  return r;
}

// The polynomial bicubic net restricted to the node: (M_ss, M_st, M_tt, the rounding guard).
// M_ss = 6·max‖Δ²_s P‖, M_st = 9·max‖Δ_sΔ_t P‖, M_tt = 6·max‖Δ²_t P‖ (the second derivatives'
// Bernstein nets, whose convex hull holds them).
vec4 bicubicSecondBounds(IN(BicubicPatch) bp, vec4 rect) {
  vec4 q[16];
  for (int k = 0; k < 16; ++k) q[k] = bp.cp[k];
  BernsteinRow4 row;
  if (rect.x != 0.0f || rect.z != 1.0f) {
    for (int j = 0; j < 4; ++j) {
      for (int i = 0; i < 4; ++i) row.c[i] = q[i * 4 + j];
      restrictBernsteinRow(row, 3, rect.x, rect.z);
      for (int i = 0; i < 4; ++i) q[i * 4 + j] = row.c[i];
    }
  }
  if (rect.y != 0.0f || rect.w != 1.0f) {
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) row.c[j] = q[i * 4 + j];
      restrictBernsteinRow(row, 3, rect.y, rect.w);
      for (int j = 0; j < 4; ++j) q[i * 4 + j] = row.c[j];
    }
  }
  PRECISE float dss = 0.0f;
  PRECISE float dst = 0.0f;
  PRECISE float dtt = 0.0f;
  PRECISE float big = 0.0f;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      vec3 p = vec3(q[i * 4 + j]);
      big = max(big, maxAbsComponent(p));
      if (i < 2) dss = max(dss, secondDifferenceNorm(p, vec3(q[(i + 1) * 4 + j]),
                                                     vec3(q[(i + 2) * 4 + j])));
      if (j < 2) dtt = max(dtt, secondDifferenceNorm(p, vec3(q[i * 4 + j + 1]),
                                                     vec3(q[i * 4 + j + 2])));
      if (i < 3 && j < 3)
        dst = max(dst, twistNorm(p, vec3(q[(i + 1) * 4 + j]), vec3(q[i * 4 + j + 1]),
                                 vec3(q[(i + 1) * 4 + j + 1])));
    }
  PRECISE float mss = 6.0f * dss;
  PRECISE float mst = 9.0f * dst;
  PRECISE float mtt = 6.0f * dtt;
  PRECISE float guard = kToleranceRoundingGuard * 18.0f * big;
  return vec4(mss, mst, mtt, guard);
}

// Rule T's equal split of a node that fails δ: the fewest children k_u·k_v (each count at
// most the cap) whose estimated bound (1 + 2⁻¹⁰)·(M_ss/k_u² + 2·M_st/(k_u·k_v) + M_tt/k_v²)/8
// + guard is within δ, as k_u | k_v << 8; 0 when no counts within the cap reach δ. Restricting
// a polynomial net to 1/k of the interval scales its second differences by at most 1/k² (the
// sub-net's scaled differences are convex combinations of the parent's), so for polynomial
// patches the children's own bounds are at most this estimate, up to rounding; rational
// children just split again where it was optimistic. Compared multiplied out by k_u²·k_v²
// (no division: GPU and mirror agree bit for bit); among equal counts, the smaller estimate.
uint toleranceGridCounts(vec4 bounds, float tolerance, uint cap) {
  PRECISE float room = tolerance - bounds.w;
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
      PRECISE float twoSt = 2.0f * bounds.y;
      PRECISE float num = (bounds.x * vv + twoSt * uv) + bounds.z * uu;
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

// The decision of rule T from the node's (M_ss, M_st, M_tt, rounding guard). With
// A = M_ss + M_st and B = M_tt + M_st, every triangle the leaf can emit (its two triangles, or
// a fan from its centre) is within (A + B)/8 of the surface (docs/quadtree.md). Not within
// δ: k_u × k_v equal children where counts within the cap reach δ (toleranceGridCounts);
// else split at the midpoint along u where A ≥ B/2, v where B ≥ A/2 (both when neither
// holds: a NaN bound).
NodeDecision toleranceDecision(vec4 bounds, IN(QuadNode) node, IN(ClassifyPush) params) {
  vec4 r = node.rect;
  PRECISE float a = bounds.x + bounds.y;
  PRECISE float b = bounds.z + bounds.y;
  PRECISE float sum = a + b;
  PRECISE float scaled = sum * 0.125f;
  PRECISE float guarded = scaled * kToleranceRelativeGuard;
  PRECISE float bound = guarded + bounds.w;
  float us = toleranceMidpoint(r.x, r.z);
  float vs = toleranceMidpoint(r.y, r.w);
  PRECISE float share = sum > 0.0f ? a / sum : 0.5f;
  NodeDecision d;
  d.split = vec4(us, vs, 0.0f, 0.0f);
  d.linearity = share;
  d.flatness = bound;
  d.pad = 0u;
  if (bound <= params.tolerance) {
    d.cause = kCauseWithinTolerance;
  } else if (node.level >= params.maxDepth) {
    d.cause = kCauseMaxDepth;
  } else if (min(r.z - r.x, r.w - r.y) < params.minSize) {
    d.cause = kCauseMinSize;
  } else {
    uint grid = toleranceGridCounts(bounds, params.tolerance, params.toleranceSplitCap);
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
