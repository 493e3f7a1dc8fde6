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

// The vertex at (u, v) from its position relative to b_00 and its two derivatives. `tol` =
// ε·L² (bicubicScale); where |Pu × Pv| ≤ tol the point is degenerate and the full rule of
// bicubicNormal (higher derivatives) gives the normal.
GridVertex gridVertexFrom(IN(BicubicPatch) bp, vec3 p, vec3 pu, vec3 pv, float u, float v,
                          float tol) {
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

// The cubic Bernstein values (b0) and derivatives (b1) at t, as gridVertex weighs a row.
void gridBasis(float t, OUT(vec4) b0, OUT(vec4) b1) {
  PRECISE float s = 1.0f - t;
  PRECISE float ss = s * s;
  PRECISE float tt = t * t;
  PRECISE float ts = t * s;
  PRECISE vec4 r0 = vec4(ss * s, 3.0f * ts * s, 3.0f * ts * t, tt * t);
  PRECISE vec4 r1 = vec4(-3.0f * ss, 3.0f * ss - 6.0f * ts, 6.0f * ts - 3.0f * tt, 3.0f * tt);
  b0 = r0;
  b1 = r1;
}

// Vertex (u, v) of the row.
GridVertex gridVertex(IN(BicubicPatch) bp, IN(GridRow) row, float u, float v, float tol) {
  vec4 b0;
  vec4 b1;
  gridBasis(v, b0, b1);
  PRECISE vec3 p = vec3(0.0f);
  PRECISE vec3 pu = vec3(0.0f);
  PRECISE vec3 pv = vec3(0.0f);
  for (int j = 0; j < 4; ++j) {
    p = p + b0[j] * row.c[j];
    pu = pu + b0[j] * row.d[j];
    pv = pv + b1[j] * row.c[j];
  }
  return gridVertexFrom(bp, p, pu, pv, u, v, tol);
}

// The u-curves through one column (fixed v): c[i] = Σ_j B_j(v) (b_ij − b_00) and d its
// v-derivative; for vertices along a side v = const (one column for the whole side instead of
// a row per vertex).
GridRow gridColumn(IN(BicubicPatch) bp, float v) {
  CubicBasis bv = cubicBasis(v);
  vec3 origin = vec3(bp.cp[0]);
  GridRow r;
  for (int i = 0; i < 4; ++i) {
    PRECISE vec3 c = vec3(0.0f);
    PRECISE vec3 d = vec3(0.0f);
    for (int j = 0; j < 4; ++j) {
      PRECISE vec3 q = vec3(bp.cp[i * 4 + j]) - origin;
      c = c + bv.b0[j] * q;
      d = d + bv.b1[j] * q;
    }
    r.c[i] = c;
    r.d[i] = d;
  }
  return r;
}

// Vertex (u, v) of the column.
GridVertex gridColumnVertex(IN(BicubicPatch) bp, IN(GridRow) column, float u, float v,
                            float tol) {
  vec4 b0;
  vec4 b1;
  gridBasis(u, b0, b1);
  PRECISE vec3 p = vec3(0.0f);
  PRECISE vec3 pu = vec3(0.0f);
  PRECISE vec3 pv = vec3(0.0f);
  for (int i = 0; i < 4; ++i) {
    p = p + b0[i] * column.c[i];
    pu = pu + b1[i] * column.c[i];
    pv = pv + b0[i] * column.d[i];
  }
  return gridVertexFrom(bp, p, pu, pv, u, v, tol);
}

#endif
