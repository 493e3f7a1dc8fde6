// Uniform-grid evaluation of a bicubic patch, one row of the grid at a time: the patch's 16
// control points collapse once per row (fixed u) into the four control points of the v-curve
// through that row and of its u-derivative curve; each vertex of the row is then a cubic in v
// (12 multiply-adds for P, Pu, Pv instead of 48 for a full point evaluation from 16 points).
// Reading the control points once per row instead of once per point is what lets lavapipe
// reach half the 5 GB/s cap (bench/README.md, case 1; one invocation per vertex was
// 2-5x slower: bench/HISTORY.md, "Findings behind the numbers").
// Compiled as GLSL (shaders/grid_eval.comp.glsl, shaders/stitch_pattern.comp.glsl) and as C++
// (host/realtime/grid_mirror.cpp, host/realtime/stitch_mirror.cpp).
// Include shared_glsl_cpp.h, layout.h and bicubic_eval.h first.
#ifndef TESSERA_GRID_EVAL_H
#define TESSERA_GRID_EVAL_H

// The v-curves through one row, relative to the patch's first control point (as in
// evalBicubic: sums of differences lose no digits to a far-away origin); or, made by
// gridCurves(…, true), the u-curves through one column (v fixed, for the sides v = 0, 1).
struct GridRow {
  vec3 c[4];  // Σ_i B_i(u) (b_ij − b_00): the curve u = const
  vec3 d[4];  // Σ_i B'_i(u) (b_ij − b_00): its u-derivative
};

// Parameter of grid line i of P (both ends exact: 0 and 1, on every driver).
float gridParam(uint i, uint pointsPerSide) { return exactRatio(i, pointsPerSide - 1u); }

// The four curves of one direction through parameter t of the other, relative to b_00: a row
// (column false: c[j] = Σ_i B_i(t) (b_ij − b_00), the v-curve u = t) or a column (column true:
// c[i] = Σ_j B_j(t) (b_ij − b_00), the u-curve v = t), and d their derivatives in t. One text
// for both, so a side of either direction runs the same instructions (no divergent lanes).
GridRow gridCurves(IN(BicubicPatch) bp, float t, bool column) {
  CubicBasis b = cubicBasis(t);
  vec3 origin = vec3(bp.cp[0]);
  GridRow r;
  for (int m = 0; m < 4; ++m) {
    PRECISE vec3 c = vec3(0.0f);
    PRECISE vec3 d = vec3(0.0f);
    for (int k = 0; k < 4; ++k) {
      PRECISE vec3 q = vec3(column ? bp.cp[m * 4 + k] : bp.cp[k * 4 + m]) - origin;
      c = c + b.b0[k] * q;
      d = d + b.b1[k] * q;
    }
    r.c[m] = c;
    r.d[m] = d;
  }
  return r;
}

GridRow gridRow(IN(BicubicPatch) bp, float u) { return gridCurves(bp, u, false); }

// A point of a row (or column) of the grid: its position relative to b_00 and its partials.
struct GridPoint {
  vec3 p;
  vec3 pu;
  vec3 pv;
};

// The unit normal Pu × Pv / |Pu × Pv| where |Pu × Pv| > `tol` (= ε·L², bicubicScale), and true;
// else vec3(0) and false: the point is degenerate, and only the full rule of bicubicNormal (higher
// derivatives, gridDegenerateNormal) gives its normal.
bool gridRegularNormal(IN(GridPoint) q, float tol, OUT(vec3) normal) {
  PRECISE vec3 n = cross(q.pu, q.pv);
  PRECISE float len = sqrt(dot(n, n));
  if (len > tol) {
    normal = scaleToUnit(n, len);
    return true;
  }
  normal = vec3(0.0f);
  return false;
}

// The normal at a degenerate point (u, v): bicubicNormal's limiting direction from the full
// derivatives at the point.
vec3 gridDegenerateNormal(IN(BicubicPatch) bp, float u, float v, float tol) {
  return bicubicNormal(evalBicubic(bp, u, v), u, v, tol);
}

// The vertex of point q with its normal.
GridVertex gridPointVertex(IN(BicubicPatch) bp, IN(GridPoint) q, vec3 normal) {
  PRECISE vec3 position = q.p + vec3(bp.cp[0]);
  GridVertex g;
  g.position = vec4(position, 1.0f);
  g.normal = vec4(normal, 0.0f);
  return g;
}

// The vertex at (u, v) from its position relative to b_00 and its two derivatives. `tol` =
// ε·L² (bicubicScale); where |Pu × Pv| ≤ tol the point is degenerate and the full rule of
// bicubicNormal (higher derivatives) gives the normal.
GridVertex gridVertexFrom(IN(BicubicPatch) bp, vec3 p, vec3 pu, vec3 pv, float u, float v,
                          float tol) {
  GridPoint q;
  q.p = p;
  q.pu = pu;
  q.pv = pv;
  vec3 normal;
  if (!gridRegularNormal(q, tol, normal)) normal = gridDegenerateNormal(bp, u, v, tol);
  return gridPointVertex(bp, q, normal);
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

// Point t of a row's (column false) or column's (true) curves: P = Σ B_k(t) c_k, its derivative
// along the curves Σ B'_k(t) c_k and across them Σ B_k(t) d_k (Pv and Pu for a row, Pu and Pv for
// a column).
GridPoint gridCurvesPoint(IN(GridRow) curves, float t, bool column) {
  vec4 b0;
  vec4 b1;
  gridBasis(t, b0, b1);
  PRECISE vec3 p = vec3(0.0f);
  PRECISE vec3 across = vec3(0.0f);
  PRECISE vec3 along = vec3(0.0f);
  for (int k = 0; k < 4; ++k) {
    p = p + b0[k] * curves.c[k];
    across = across + b0[k] * curves.d[k];
    along = along + b1[k] * curves.c[k];
  }
  GridPoint q;
  q.p = p;
  q.pu = column ? along : across;
  q.pv = column ? across : along;
  return q;
}

GridPoint gridRowPoint(IN(GridRow) row, float v) { return gridCurvesPoint(row, v, false); }

// Vertex (u, v) of the row.
GridVertex gridVertex(IN(BicubicPatch) bp, IN(GridRow) row, float u, float v, float tol) {
  GridPoint q = gridRowPoint(row, v);
  return gridVertexFrom(bp, q.p, q.pu, q.pv, u, v, tol);
}

#endif
