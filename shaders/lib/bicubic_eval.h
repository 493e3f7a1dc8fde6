// Bicubic Bézier evaluation in fp32: derivatives to third order, the unit normal with the
// degenerate-point rule and κ, both as in docs/conventions.md; and a mesh vertex's position and
// normal alone (evalBicubicVertex), the same bits for less work.
// Compiled twice from this one text: as GLSL in shaders/*.comp.glsl and as C++ in
// host/eval/bicubic_mirror.cpp. Include shared_glsl_cpp.h and layout.h first.
#ifndef TESSERA_BICUBIC_EVAL_H
#define TESSERA_BICUBIC_EVAL_H

// eval.comp.glsl defines BICUBIC_EVAL_UNROLL [[unroll]]: these loops have constant trip counts
// and no break, so spirv-opt unrolls them and lavapipe, which compiles the pipeline at every
// run, gets straight-line code instead of unrolling them itself (vkCreateComputePipelines
// ~4.5 → ~3.7 ms of thread CPU; bench/HISTORY.md). The same operations in the same order.
// Elsewhere (the mirror, the other shaders) they stay loops.
#ifndef BICUBIC_EVAL_UNROLL
#define BICUBIC_EVAL_UNROLL
#endif

struct CubicBasis {
  vec4 b0;  // Bernstein B_i,3(t)
  vec4 b1;  // first derivative
  vec4 b2;  // second derivative
  vec4 b3;  // third derivative (constant)
};

struct BicubicDerivs {
  vec3 p;
  vec3 pu;
  vec3 pv;
  vec3 puu;
  vec3 puv;
  vec3 pvv;
  vec3 puuu;
  vec3 puuv;
  vec3 puvv;
  vec3 pvvv;
};

CubicBasis cubicBasis(float t) {
  PRECISE float s = 1.0f - t;
  PRECISE float ss = s * s;
  PRECISE float tt = t * t;
  PRECISE float ts = t * s;
  CubicBasis r;
  r.b0 = vec4(ss * s, 3.0f * ts * s, 3.0f * ts * t, tt * t);
  r.b1 = vec4(-3.0f * ss, 3.0f * ss - 6.0f * ts, 6.0f * ts - 3.0f * tt, 3.0f * tt);
  r.b2 = vec4(6.0f * s, 6.0f * t - 12.0f * s, 6.0f * s - 12.0f * t, 6.0f * t);
  r.b3 = vec4(-6.0f, 18.0f, -18.0f, 6.0f);
  return r;
}

// Sums along v first (one row of four control points at a time), then along u: the row
// partial sums are shared by all ten derivatives. Control points are taken relative to the
// first one: derivative sums cancel (Σ B'_i = 0), and cancelling coordinates far from the
// origin would cost fp32 digits in proportion to the offset instead of the patch's size.
BicubicDerivs evalBicubic(IN(BicubicPatch) bp, float u, float v) {
  vec3 origin = vec3(bp.cp[0]);
  CubicBasis bu = cubicBasis(u);
  CubicBasis bv = cubicBasis(v);
  BicubicDerivs d;
  d.p = vec3(0.0f);
  d.pu = vec3(0.0f);
  d.pv = vec3(0.0f);
  d.puu = vec3(0.0f);
  d.puv = vec3(0.0f);
  d.pvv = vec3(0.0f);
  d.puuu = vec3(0.0f);
  d.puuv = vec3(0.0f);
  d.puvv = vec3(0.0f);
  d.pvvv = vec3(0.0f);
  BICUBIC_EVAL_UNROLL for (int i = 0; i < 4; ++i) {
    PRECISE vec3 r0 = vec3(0.0f);
    PRECISE vec3 r1 = vec3(0.0f);
    PRECISE vec3 r2 = vec3(0.0f);
    PRECISE vec3 r3 = vec3(0.0f);
    BICUBIC_EVAL_UNROLL for (int j = 0; j < 4; ++j) {
      PRECISE vec3 q = vec3(bp.cp[i * 4 + j]) - origin;
      r0 = r0 + bv.b0[j] * q;
      r1 = r1 + bv.b1[j] * q;
      r2 = r2 + bv.b2[j] * q;
      r3 = r3 + bv.b3[j] * q;
    }
    PRECISE vec3 p = d.p + bu.b0[i] * r0;
    PRECISE vec3 pu = d.pu + bu.b1[i] * r0;
    PRECISE vec3 pv = d.pv + bu.b0[i] * r1;
    PRECISE vec3 puu = d.puu + bu.b2[i] * r0;
    PRECISE vec3 puv = d.puv + bu.b1[i] * r1;
    PRECISE vec3 pvv = d.pvv + bu.b0[i] * r2;
    PRECISE vec3 puuu = d.puuu + bu.b3[i] * r0;
    PRECISE vec3 puuv = d.puuv + bu.b2[i] * r1;
    PRECISE vec3 puvv = d.puvv + bu.b1[i] * r2;
    PRECISE vec3 pvvv = d.pvvv + bu.b0[i] * r3;
    // Through PRECISE locals into d (here and in evalGeneral), not d.p = d.p + …: `precise`
    // marks the operations that compute a precise variable, and a member of d is not one.
    d.p = p;
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

// A mesh vertex's share of evalBicubic: the position and the first partials, which are all the
// normal needs away from degenerate points.
struct BicubicFirstDerivs {
  vec3 p;
  vec3 pu;
  vec3 pv;
};

// evalBicubic's p, pu and pv by the very operations, in the same order, that evalBicubic runs
// for them: each of its ten sums is a chain of its own (r0 and r1 feed them, r2 and r3 only the
// higher partials), so leaving the other seven out changes no bit. A copy of evalBicubic's loop
// cut down, not a call: a vertex pays for three sums instead of ten.
BicubicFirstDerivs evalBicubicFirst(IN(BicubicPatch) bp, float u, float v) {
  vec3 origin = vec3(bp.cp[0]);
  CubicBasis bu = cubicBasis(u);
  CubicBasis bv = cubicBasis(v);
  BicubicFirstDerivs d;
  d.p = vec3(0.0f);
  d.pu = vec3(0.0f);
  d.pv = vec3(0.0f);
  BICUBIC_EVAL_UNROLL for (int i = 0; i < 4; ++i) {
    PRECISE vec3 r0 = vec3(0.0f);
    PRECISE vec3 r1 = vec3(0.0f);
    BICUBIC_EVAL_UNROLL for (int j = 0; j < 4; ++j) {
      PRECISE vec3 q = vec3(bp.cp[i * 4 + j]) - origin;
      r0 = r0 + bv.b0[j] * q;
      r1 = r1 + bv.b1[j] * q;
    }
    PRECISE vec3 p = d.p + bu.b0[i] * r0;
    PRECISE vec3 pu = d.pu + bu.b1[i] * r0;
    PRECISE vec3 pv = d.pv + bu.b0[i] * r1;
    d.p = p;
    d.pu = pu;
    d.pv = pv;
  }
  PRECISE vec3 position = d.p + origin;
  d.p = position;
  return d;
}

// Diagonal of the control net's bounding box: the length scale L of the degeneracy test.
float bicubicScale(IN(BicubicPatch) bp) {
  PRECISE vec3 lo = vec3(bp.cp[0]);
  PRECISE vec3 hi = lo;
  BICUBIC_EVAL_UNROLL for (int k = 1; k < 16; ++k) {
    lo = min(lo, vec3(bp.cp[k]));
    hi = max(hi, vec3(bp.cp[k]));
  }
  PRECISE vec3 e = hi - lo;
  PRECISE float l = sqrt(dot(e, e));
  return l;
}

// n / |n|, written as a product with one reciprocal so both compilers round the same way.
vec3 scaleToUnit(vec3 n, float len) {
  PRECISE float inv = 1.0f / len;
  PRECISE vec3 r = n * inv;
  return r;
}

// The normal's first case, n = Pu × Pv / |Pu × Pv|, where |Pu × Pv| > tol: returns whether it
// applies; where it does not (a degenerate point: the caller's rule), n = vec3(0). Forced inline:
// GCC left it a call per vertex in general_mirror.cpp, where the code it replaced was inlined.
SHARED_FORCE_INLINE bool unitNormalFromFirst(vec3 pu, vec3 pv, float tol, OUT(vec3) n) {
  PRECISE vec3 n0 = cross(pu, pv);
  PRECISE float len0 = sqrt(dot(n0, n0));
  bool regular = len0 > tol;
  n = vec3(0.0f);
  if (regular) n = scaleToUnit(n0, len0);
  return regular;  // one return: no early exit for spirv-opt's merge-return to wrap in a loop
}

// Unit normal; at degenerate points the limiting direction from inside the patch
// (docs/conventions.md). `tol` is ε·L². Returns vec3(0) where no direction exists.
vec3 bicubicNormal(IN(BicubicDerivs) d, float u, float v, float tol) {
  vec3 n;
  if (unitNormalFromFirst(d.pu, d.pv, tol, n)) return n;

  PRECISE float du = 0.5f - u;
  PRECISE float dv = 0.5f - v;
  PRECISE float dl = sqrt(du * du + dv * dv);
  if (dl > 0.0f) {
    du = du / dl;
    dv = dv / dl;
  } else {
    du = 0.70710678f;
    dv = 0.70710678f;
  }
  PRECISE vec3 a1 = du * d.puu + dv * d.puv;
  PRECISE vec3 b1 = du * d.puv + dv * d.pvv;
  PRECISE vec3 n1 = cross(a1, d.pv) + cross(d.pu, b1);
  PRECISE float len1 = sqrt(dot(n1, n1));
  if (len1 > tol) return scaleToUnit(n1, len1);

  PRECISE float uu = du * du;
  PRECISE float uv2 = 2.0f * du * dv;
  PRECISE float vv = dv * dv;
  PRECISE vec3 a2 = uu * d.puuu + uv2 * d.puuv + vv * d.puvv;
  PRECISE vec3 b2 = uu * d.puuv + uv2 * d.puvv + vv * d.pvvv;
  PRECISE vec3 n2 = cross(a2, d.pv) + 2.0f * cross(a1, b1) + cross(d.pu, b2);
  PRECISE float len2 = sqrt(dot(n2, n2));
  if (len2 > tol) return scaleToUnit(n2, len2);
  return vec3(0.0f);
}

// κ = max |principal curvature|; 0 where the first fundamental form is singular.
float bicubicKappa(IN(BicubicDerivs) d, vec3 n, float tol) {
  PRECISE float e = dot(d.pu, d.pu);
  PRECISE float f = dot(d.pu, d.pv);
  PRECISE float g = dot(d.pv, d.pv);
  PRECISE float l = dot(d.puu, n);
  PRECISE float m = dot(d.puv, n);
  PRECISE float nn = dot(d.pvv, n);
  PRECISE float det = e * g - f * f;
  if (!(det > tol * tol)) return 0.0f;
  PRECISE float gaussK = (l * nn - m * m) / det;
  PRECISE float meanH = (e * nn - 2.0f * f * m + g * l) / (2.0f * det);
  PRECISE float disc = max(meanH * meanH - gaussK, 0.0f);
  PRECISE float kappa = abs(meanH) + sqrt(disc);
  return kappa;
}

// The sample of derivatives `d` at (u, v) of a patch of length scale `scale` (shared with
// general_eval.h: any patch's derivatives give its normal and κ the same way).
EvalSample sampleFromDerivs(IN(BicubicDerivs) d, float u, float v, float scale, float eps) {
  PRECISE float tol = eps * scale * scale;
  vec3 n = bicubicNormal(d, u, v, tol);
  float kappa = bicubicKappa(d, n, tol);
  EvalSample s;
  s.position = vec4(d.p, 1.0f);
  s.du = vec4(d.pu, 0.0f);
  s.dv = vec4(d.pv, 0.0f);
  s.normalKappa = vec4(n, kappa);
  return s;
}

EvalSample evalBicubicSample(IN(BicubicPatch) bp, float u, float v, float eps) {
  return sampleFromDerivs(evalBicubic(bp, u, v), u, v, bicubicScale(bp), eps);
}

// evalBicubicSample's position and normal, bit for bit, without κ and the partials a mesh does
// not keep: the first partials give the normal where |Pu × Pv| > tol (unitNormalFromFirst,
// bicubicNormal's first case); elsewhere the full derivatives are evaluated and bicubicNormal's
// degenerate rule runs as in evalBicubicSample.
// `tol` is ε·L² (bicubicTolerance), sampleFromDerivs' tol.
VertexSample bicubicVertex(IN(BicubicPatch) bp, float u, float v, float tol) {
  BicubicFirstDerivs d = evalBicubicFirst(bp, u, v);
  vec3 n;
  if (!unitNormalFromFirst(d.pu, d.pv, tol, n)) {
    n = bicubicNormal(evalBicubic(bp, u, v), u, v, tol);
  }
  VertexSample s;
  s.position = vec4(d.p, 1.0f);
  s.normal = vec4(n, 0.0f);
  return s;
}

// ε·L², as sampleFromDerivs computes it from bicubicScale: one patch's, for all its vertices.
float bicubicTolerance(IN(BicubicPatch) bp, float eps) {
  PRECISE float scale = bicubicScale(bp);
  PRECISE float tol = eps * scale * scale;
  return tol;
}

VertexSample evalBicubicVertex(IN(BicubicPatch) bp, float u, float v, float eps) {
  return bicubicVertex(bp, u, v, bicubicTolerance(bp, eps));
}

#endif
