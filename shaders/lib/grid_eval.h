// Uniform-grid evaluation of a bicubic patch, one row of the grid at a time: the patch's 16
// control points collapse once per row (fixed u) into the four control points of the v-curve
// through that row and of its u-derivative curve; each vertex of the row is then a cubic in v
// (12 multiply-adds for P, Pu, Pv instead of 48 for a full point evaluation from 16 points).
// Reading the control points once per row instead of once per point is what lets lavapipe
// reach the memory-bandwidth cap (bench/README.md, case 1).
// Compiled as GLSL (shaders/grid_eval.comp.glsl) and as C++ (host/realtime/grid_mirror.cpp).
// Include shared_glsl_cpp.h, layout.h and bicubic_eval.h first.
#ifndef TESSERA_GRID_EVAL_H
#define TESSERA_GRID_EVAL_H

// The v-curves through one row, relative to the patch's first control point (as in
// evalBicubic: sums of differences lose no digits to a far-away origin).
struct GridRow {
  vec3 c[4];  // Σ_i B_i(u) (b_ij − b_00): the curve u = const
  vec3 d[4];  // Σ_i B'_i(u) (b_ij − b_00): its u-derivative
};

// Parameter of grid line i of P (both ends exact: 0 and 1).
float gridParam(uint i, uint pointsPerSide) {
  PRECISE float t = float(i) / float(pointsPerSide - 1u);
  return t;
}

GridRow gridRow(IN(BicubicPatch) bp, float u) {
  CubicBasis bu = cubicBasis(u);
  vec3 origin = vec3(bp.cp[0]);
  GridRow r;
  for (int j = 0; j < 4; ++j) {
    PRECISE vec3 c = vec3(0.0f);
    PRECISE vec3 d = vec3(0.0f);
    for (int i = 0; i < 4; ++i) {
      PRECISE vec3 q = vec3(bp.cp[i * 4 + j]) - origin;
      c = c + bu.b0[i] * q;
      d = d + bu.b1[i] * q;
    }
    r.c[j] = c;
    r.d[j] = d;
  }
  return r;
}

// Vertex (u, v) of the row. `tol` = ε·L² (bicubicScale); where |Pu × Pv| ≤ tol the point is
// degenerate and the full rule of bicubicNormal (higher derivatives) gives the normal.
GridVertex gridVertex(IN(BicubicPatch) bp, IN(GridRow) row, float u, float v, float tol) {
  PRECISE float s = 1.0f - v;
  PRECISE float ss = s * s;
  PRECISE float vv = v * v;
  PRECISE float vs = v * s;
  PRECISE vec4 b0 = vec4(ss * s, 3.0f * vs * s, 3.0f * vs * v, vv * v);
  PRECISE vec4 b1 = vec4(-3.0f * ss, 3.0f * ss - 6.0f * vs, 6.0f * vs - 3.0f * vv, 3.0f * vv);
  PRECISE vec3 p = vec3(0.0f);
  PRECISE vec3 pu = vec3(0.0f);
  PRECISE vec3 pv = vec3(0.0f);
  for (int j = 0; j < 4; ++j) {
    p = p + b0[j] * row.c[j];
    pu = pu + b0[j] * row.d[j];
    pv = pv + b1[j] * row.c[j];
  }
  PRECISE vec3 n = cross(pu, pv);
  PRECISE float len = sqrt(dot(n, n));
  vec3 normal;
  if (len > tol)
    normal = scaleToUnit(n, len);
  else
    normal = bicubicNormal(evalBicubic(bp, u, v), u, v, tol);
  PRECISE vec3 position = p + vec3(bp.cp[0]);
  GridVertex g;
  g.position = vec4(position, 1.0f);
  g.normal = vec4(normal, 0.0f);
  return g;
}

#endif
