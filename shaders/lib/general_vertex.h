// A mesh vertex of a general patch (position and unit normal) from first partials alone:
// evalGeneralSample's position and normal bits for less work, as bicubicVertex is for bicubic
// patches. Each value below is computed by the same operations, in the same order, as
// evalGeneral and sampleFromDerivs compute it; only what a vertex does not keep is left out
// (the second and third partials, κ), and the patch's length scale is computed once per patch
// (generalTolerance) instead of once per vertex.
// Written in the shared GLSL/C++ dialect beside general_eval.h, compiled today as C++ only
// (host/eval/general_mirror.cpp): a Vulkan shader on it (eval_general_vertices.comp, branch
// eval38) was bit-exact on lavapipe but no faster in bench_cad (bench/HISTORY.md), so Vulkan
// keeps eval_general.comp's full samples. Include general_eval.h (and what it needs) first.
#ifndef TESSERA_GENERAL_VERTEX_H
#define TESSERA_GENERAL_VERTEX_H

// bernsteinDerivs' b0 and b1 rows. Entry i ≤ n of the triangle depends only on entries ≤ i,
// so the rows stop at n; entries past n stay zero, as bernsteinDerivs leaves them.
struct BernsteinFirst {
  Row8 b0;
  Row8 b1;
};

BernsteinFirst bernsteinFirst(int n, float t) {
  PRECISE float s = 1.0f - t;
  Row8 r = zeroRow();
  r.v[0] = 1.0f;
  Row8 d1 = zeroRow();
  if (n == 1) d1 = r;  // bernsteinDerivs' k = 0 step
  for (int k = 1; k <= n; ++k) {
    for (int i = n; i >= 1; --i) {
      PRECISE float x = s * r.v[i] + t * r.v[i - 1];
      r.v[i] = x;
    }
    PRECISE float x0 = s * r.v[0];
    r.v[0] = x0;
    if (k == n - 1) d1 = r;
  }
  PRECISE float c1 = float(n);
  BernsteinFirst b;
  b.b0 = r;
  b.b1 = zeroRow();
  for (int i = 0; i <= n; ++i) {
    PRECISE float e1 = c1 * (rowAt(d1, i - 1) - rowAt(d1, i));
    b.b1.v[i] = e1;
  }
  return b;
}

// sampleFromDerivs' tol = ε·L², L being generalScale's: the same for every vertex of a patch.
float generalTolerance(IN(GeneralPatch) gp, float eps) {
  PRECISE float scale = generalScale(gp);
  PRECISE float tol = eps * scale * scale;
  return tol;
}

// evalGeneral's H^(0,0), H^(1,0), H^(0,1) and its quotient rule to first order give the
// position and Pu × Pv; where |Pu × Pv| ≤ tol the full derivatives are evaluated and
// bicubicNormal's degenerate rule runs as in evalGeneralSample. The degrees and kind come as
// arguments (the patch's own: generalVertex) so that the C++ mirror can pass constants for the
// common pairs and have the loops unrolled (general_mirror.cpp); the operations are the same
// either way. `tol` is generalTolerance's.
SHARED_FORCE_INLINE VertexSample generalVertexOfDegrees(IN(GeneralPatch) gp, int n, int m,
                                                        bool rational, float u, float v,
                                                        float tol) {
  vec4 first = controlPoints[gp.firstPoint];
  vec3 origin = rational ? projected(first) : vec3(first);
  BernsteinFirst bu = bernsteinFirst(n, u);
  BernsteinFirst bv = bernsteinFirst(m, v);
  vec4 h00 = vec4(0.0f);
  vec4 h10 = vec4(0.0f);
  vec4 h01 = vec4(0.0f);
  for (int i = 0; i <= n; ++i) {
    PRECISE vec4 r0 = vec4(0.0f);
    PRECISE vec4 r1 = vec4(0.0f);
    for (int j = 0; j <= m; ++j) {
      vec4 c = controlPoints[gp.firstPoint + uint(i * (m + 1) + j)];  // generalPoint's b_ij
      PRECISE vec3 rel = vec3(c) - (rational ? c.w * origin : origin);
      PRECISE vec4 q = vec4(rel, rational ? c.w : 1.0f);
      r0 = r0 + bv.b0.v[j] * q;
      r1 = r1 + bv.b1.v[j] * q;
    }
    PRECISE vec4 a00 = h00 + bu.b0.v[i] * r0;
    PRECISE vec4 a10 = h10 + bu.b1.v[i] * r0;
    PRECISE vec4 a01 = h01 + bu.b0.v[i] * r1;
    h00 = a00;
    h10 = a10;
    h01 = a01;
  }
  vec3 p = vec3(h00);
  vec3 pu = vec3(h10);
  vec3 pv = vec3(h01);
  if (rational) {
    PRECISE float inv = 1.0f / h00.w;
    PRECISE vec3 q = p * inv;
    PRECISE vec3 qu = (pu - h10.w * q) * inv;
    PRECISE vec3 qv = (pv - h01.w * q) * inv;
    p = q;
    pu = qu;
    pv = qv;
  }
  PRECISE vec3 position = p + origin;
  vec3 normal;
  if (!unitNormalFromFirst(pu, pv, tol, normal)) {
    normal = bicubicNormal(evalGeneral(gp, u, v), u, v, tol);
  }
  VertexSample s;
  s.position = vec4(position, 1.0f);
  s.normal = vec4(normal, 0.0f);
  return s;
}

VertexSample generalVertex(IN(GeneralPatch) gp, float u, float v, float tol) {
  return generalVertexOfDegrees(gp, int(gp.degreeU), int(gp.degreeV), gp.rational != 0u, u, v,
                                tol);
}

#endif
