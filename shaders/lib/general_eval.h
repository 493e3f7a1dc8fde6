// Evaluation of a general tensor-product Bézier patch (degree 1..7 each way, polynomial or
// rational) in fp32: the ten partial derivatives to third order that bicubic_eval.h gives for
// bicubic patches, so the unit normal (degenerate rule included) and κ are bicubic_eval.h's.
// Every loop runs to kGeneralMaxOrder with the degree as a guard: one code path, any degree.
// Compiled twice from this one text: GLSL (shaders/eval_general.comp.glsl,
// quadtree_general.comp.glsl) and C++ (host/eval/general_mirror.cpp); a mesh vertex's share
// is lib/general_vertex.h. Both declare
// `controlPoints` (vec4 w·x, w·y, w·z, w) before including this; include shared_glsl_cpp.h,
// layout.h and bicubic_eval.h first.
#ifndef TESSERA_GENERAL_EVAL_H
#define TESSERA_GENERAL_EVAL_H

struct Row8 {
  float v[8];
};

// Bernstein polynomials B_i,n(t) and their first three derivatives, zero for i > n.
struct BernsteinDerivs {
  Row8 b0;
  Row8 b1;
  Row8 b2;
  Row8 b3;
};

Row8 zeroRow() {
  Row8 r;
  for (int i = 0; i < kGeneralMaxOrder; ++i) r.v[i] = 0.0f;
  return r;
}

float rowAt(IN(Row8) r, int i) { return i < 0 ? 0.0f : r.v[i]; }

// The basis of degree n by the triangle B_i,k = (1−t) B_i,k−1 + t B_i−1,k−1, keeping the rows
// of degree n−1, n−2, n−3 for the derivatives (Farin, "Curves and Surfaces for CAGD", §5.3):
// B'_i,n = n (B_i−1,n−1 − B_i,n−1), and the second and third forward differences likewise.
BernsteinDerivs bernsteinDerivs(int n, float t) {
  PRECISE float s = 1.0f - t;
  Row8 r = zeroRow();
  r.v[0] = 1.0f;
  Row8 d1 = zeroRow();
  Row8 d2 = zeroRow();
  Row8 d3 = zeroRow();
  for (int k = 0; k < kGeneralMaxOrder; ++k) {
    if (k > 0 && k <= n) {
      for (int i = kGeneralMaxOrder - 1; i >= 1; --i) {
        PRECISE float x = s * r.v[i] + t * r.v[i - 1];
        r.v[i] = x;
      }
      PRECISE float x0 = s * r.v[0];
      r.v[0] = x0;
    }
    if (k == n - 1) d1 = r;
    if (k == n - 2) d2 = r;
    if (k == n - 3) d3 = r;
  }
  PRECISE float c1 = float(n);
  PRECISE float c2 = float(n * (n - 1));
  PRECISE float c3 = float(n * (n - 1) * (n - 2));
  BernsteinDerivs b;
  b.b0 = r;
  for (int i = 0; i < kGeneralMaxOrder; ++i) {
    PRECISE float e1 = c1 * (rowAt(d1, i - 1) - rowAt(d1, i));
    PRECISE float e2 = c2 * ((rowAt(d2, i - 2) - 2.0f * rowAt(d2, i - 1)) + rowAt(d2, i));
    PRECISE float e3 = c3 * (((rowAt(d3, i - 3) - 3.0f * rowAt(d3, i - 2)) +
                              3.0f * rowAt(d3, i - 1)) - rowAt(d3, i));
    b.b1.v[i] = e1;
    b.b2.v[i] = e2;
    b.b3.v[i] = e3;
  }
  return b;
}

vec4 generalPoint(IN(GeneralPatch) gp, int i, int j) {
  return controlPoints[gp.firstPoint + uint(i * (int(gp.degreeV) + 1) + j)];
}

// The affine position of a control point (w > 0).
vec3 projected(vec4 h) {
  PRECISE float inv = 1.0f / h.w;
  PRECISE vec3 p = vec3(h) * inv;
  return p;
}

// Homogeneous partials H^(a,b) (a + b ≤ 3) as bicubic_eval.h sums them: along v first, then
// along u; then for a rational patch the quotient rule S = (A − Σ C(a,i)C(b,j) w^(i,j)
// S^(a−i,b−j)) / w (The NURBS Book, eq. 4.20, written out to third order). Control points
// are taken relative to b_00's position, as in evalBicubic, so fp32 keeps the patch's digits.
BicubicDerivs evalGeneral(IN(GeneralPatch) gp, float u, float v) {
  int n = int(gp.degreeU);
  int m = int(gp.degreeV);
  bool rational = gp.rational != 0u;
  vec4 first = generalPoint(gp, 0, 0);
  vec3 origin = rational ? projected(first) : vec3(first);
  BernsteinDerivs bu = bernsteinDerivs(n, u);
  BernsteinDerivs bv = bernsteinDerivs(m, v);
  vec4 h00 = vec4(0.0f);
  vec4 h10 = vec4(0.0f);
  vec4 h01 = vec4(0.0f);
  vec4 h20 = vec4(0.0f);
  vec4 h11 = vec4(0.0f);
  vec4 h02 = vec4(0.0f);
  vec4 h30 = vec4(0.0f);
  vec4 h21 = vec4(0.0f);
  vec4 h12 = vec4(0.0f);
  vec4 h03 = vec4(0.0f);
  for (int i = 0; i < kGeneralMaxOrder; ++i) {
    if (i > n) break;
    PRECISE vec4 r0 = vec4(0.0f);
    PRECISE vec4 r1 = vec4(0.0f);
    PRECISE vec4 r2 = vec4(0.0f);
    PRECISE vec4 r3 = vec4(0.0f);
    for (int j = 0; j < kGeneralMaxOrder; ++j) {
      if (j > m) break;
      vec4 c = generalPoint(gp, i, j);
      PRECISE vec3 rel = vec3(c) - (rational ? c.w * origin : origin);
      PRECISE vec4 q = vec4(rel, rational ? c.w : 1.0f);
      r0 = r0 + bv.b0.v[j] * q;
      r1 = r1 + bv.b1.v[j] * q;
      r2 = r2 + bv.b2.v[j] * q;
      r3 = r3 + bv.b3.v[j] * q;
    }
    PRECISE vec4 a00 = h00 + bu.b0.v[i] * r0;
    PRECISE vec4 a10 = h10 + bu.b1.v[i] * r0;
    PRECISE vec4 a01 = h01 + bu.b0.v[i] * r1;
    PRECISE vec4 a20 = h20 + bu.b2.v[i] * r0;
    PRECISE vec4 a11 = h11 + bu.b1.v[i] * r1;
    PRECISE vec4 a02 = h02 + bu.b0.v[i] * r2;
    PRECISE vec4 a30 = h30 + bu.b3.v[i] * r0;
    PRECISE vec4 a21 = h21 + bu.b2.v[i] * r1;
    PRECISE vec4 a12 = h12 + bu.b1.v[i] * r2;
    PRECISE vec4 a03 = h03 + bu.b0.v[i] * r3;
    h00 = a00;
    h10 = a10;
    h01 = a01;
    h20 = a20;
    h11 = a11;
    h02 = a02;
    h30 = a30;
    h21 = a21;
    h12 = a12;
    h03 = a03;
  }
  BicubicDerivs d;
  d.p = vec3(h00);
  d.pu = vec3(h10);
  d.pv = vec3(h01);
  d.puu = vec3(h20);
  d.puv = vec3(h11);
  d.pvv = vec3(h02);
  d.puuu = vec3(h30);
  d.puuv = vec3(h21);
  d.puvv = vec3(h12);
  d.pvvv = vec3(h03);
  if (rational) {
    // Leibniz on A = w·S, solved for the highest derivative of S, lowest orders first.
    PRECISE float inv = 1.0f / h00.w;
    PRECISE vec3 p = d.p * inv;
    PRECISE vec3 pu = (d.pu - h10.w * p) * inv;
    PRECISE vec3 pv = (d.pv - h01.w * p) * inv;
    PRECISE vec3 puu = ((d.puu - 2.0f * h10.w * pu) - h20.w * p) * inv;
    PRECISE vec3 puv = (((d.puv - h10.w * pv) - h01.w * pu) - h11.w * p) * inv;
    PRECISE vec3 pvv = ((d.pvv - 2.0f * h01.w * pv) - h02.w * p) * inv;
    PRECISE vec3 puuu = (((d.puuu - 3.0f * h10.w * puu) - 3.0f * h20.w * pu) - h30.w * p) * inv;
    PRECISE vec3 puuv = (((((d.puuv - h01.w * puu) - 2.0f * h10.w * puv) - 2.0f * h11.w * pu) -
                          h20.w * pv) - h21.w * p) * inv;
    PRECISE vec3 puvv = (((((d.puvv - h10.w * pvv) - 2.0f * h01.w * puv) - 2.0f * h11.w * pv) -
                          h02.w * pu) - h12.w * p) * inv;
    PRECISE vec3 pvvv = (((d.pvvv - 3.0f * h01.w * pvv) - 3.0f * h02.w * pv) - h03.w * p) * inv;
    d.p = p;  // through PRECISE locals, as in evalBicubic
    d.pu = pu;
    d.pv = pv;
    d.puu = puu;
    d.puv = puv;
    d.pvv = pvv;
    d.puuu = puuu;
    d.puuv = puuv;
    d.puvv = puvv;
    d.pvvv = pvvv;
  }
  PRECISE vec3 position = d.p + origin;
  d.p = position;
  return d;
}

// The length scale L of the degeneracy test: the diagonal of the bounding box of the control
// points' positions, points of weight 0 (directions, not positions) left out.
float generalScale(IN(GeneralPatch) gp) {
  int n = int(gp.degreeU);
  int m = int(gp.degreeV);
  bool rational = gp.rational != 0u;
  PRECISE vec3 lo = rational ? projected(generalPoint(gp, 0, 0)) : vec3(generalPoint(gp, 0, 0));
  PRECISE vec3 hi = lo;
  for (int i = 0; i < kGeneralMaxOrder; ++i) {
    if (i > n) break;
    for (int j = 0; j < kGeneralMaxOrder; ++j) {
      if (j > m) break;
      vec4 c = generalPoint(gp, i, j);
      if (rational && !(c.w > 0.0f)) continue;
      vec3 p = rational ? projected(c) : vec3(c);
      lo = min(lo, p);
      hi = max(hi, p);
    }
  }
  PRECISE vec3 e = hi - lo;
  PRECISE float l = sqrt(dot(e, e));
  return l;
}

EvalSample evalGeneralSample(IN(GeneralPatch) gp, float u, float v, float eps) {
  return sampleFromDerivs(evalGeneral(gp, u, v), u, v, generalScale(gp), eps);
}

#endif
