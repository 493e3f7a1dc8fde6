// The stitched pattern of one patch (docs/realtime.md draws it): an inner grid of cu × cv
// vertices from the patch's counts, and on each side a strip joining the inner grid's outer
// row or column to the side's own edge count. Counts, offsets, the zipper rule of a strip and
// the vertex of an edge; the buffer writes are in stitch_pattern.comp.glsl and its mirror.
// Compiled as GLSL and as C++ (host/realtime/stitch_mirror.cpp, host/realtime/frame_vulkan.cpp).
// Include shared_glsl_cpp.h and layout.h first.
#ifndef TESSERA_STITCH_PATTERN_H
#define TESSERA_STITCH_PATTERN_H

// Inner vertices along a direction of count n: the grid lines i/n, 0 < i < n; one line at 1/2
// when n = 1 (the strips of opposite sides then meet on it).
uint stitchInner(uint n) { return n >= 2u ? n - 1u : 1u; }

// Parameter of inner line i (0 ≤ i < stitchInner(n)).
float stitchInnerParam(uint i, uint n) { return n >= 2u ? exactRatio(i + 1u, n) : 0.5f; }

// Count n and inner vertices c along side s (V0 and V1 run along u, U1 and U0 along v).
uint stitchSideCount(IN(StitchPatch) sp, uint s) { return (s & 1u) == 0u ? sp.nu : sp.nv; }

uint stitchStripTriangles(IN(StitchPatch) sp, uint s) {
  uint c = stitchInner(stitchSideCount(sp, s));
  // An outer step per edge segment and an inner step per inner segment; a collapsed side's
  // outer steps would be zero-area triangles and are left out.
  return (sp.sideFlags[s] & kStitchCollapsed) != 0u ? c - 1u : sp.sideSegments[s] + c - 1u;
}

uint stitchInnerTriangles(IN(StitchPatch) sp) {
  return 2u * (stitchInner(sp.nu) - 1u) * (stitchInner(sp.nv) - 1u);
}

// First vertex of side s's edge points (the inner grid comes first, row-major i·cv + j).
uint stitchSideFirstVertex(IN(StitchPatch) sp, uint s) {
  uint first = stitchInner(sp.nu) * stitchInner(sp.nv);
  for (uint k = 0u; k < s; ++k) first += sp.sideSegments[k] + 1u;
  return first;
}

// First triangle of side s's strip (the inner grid's cells come first).
uint stitchSideFirstTriangle(IN(StitchPatch) sp, uint s) {
  uint first = stitchInnerTriangles(sp);
  for (uint k = 0u; k < s; ++k) first += stitchStripTriangles(sp, k);
  return first;
}

uint stitchVertexCount(IN(StitchPatch) sp) { return stitchSideFirstVertex(sp, 4u); }
uint stitchTriangleCount(IN(StitchPatch) sp) { return stitchSideFirstTriangle(sp, 4u); }

// Local index of the inner vertex next to side s, number i along the side's t.
uint stitchInnerAlongSide(IN(StitchPatch) sp, uint s, uint i) {
  uint cu = stitchInner(sp.nu);
  uint cv = stitchInner(sp.nv);
  if (s == 0u) return i * cv;                 // V0: row j = 0
  if (s == 1u) return (cu - 1u) * cv + i;     // U1: column i = cu − 1
  if (s == 2u) return i * cv + cv - 1u;       // V1: row j = cv − 1
  return i;                                   // U0: column i = 0
}

// The zipper of a strip: with edge point k (of e) and inner vertex i (of c, lines of count n)
// as the last two joined, the next triangle advances along the edge when the middle of the
// next edge segment, (k + 1/2)/e, is at most the middle of the next inner segment,
// (i + 3/2)/n (inner line i is at (i + 1)/n); in integers, exact.
bool stitchAdvanceOuter(uint k, uint e, uint i, uint c, uint n) {
  if (k >= e) return false;
  if (i + 1u >= c) return true;
  return (2u * k + 1u) * n <= (2u * i + 3u) * e;
}

// Point t of a cubic edge from its four canonical control points, plain Bernstein sums with no
// origin shift: t = 0 and t = 1 give the end points exactly, and both patches of a shared edge
// run this same arithmetic on the same data, so their vertices agree bit for bit.
vec3 stitchEdgePoint(IN(vec4) p0, IN(vec4) p1, IN(vec4) p2, IN(vec4) p3, float t) {
  PRECISE float s = 1.0f - t;
  PRECISE float b0 = s * s * s;
  PRECISE float b1 = 3.0f * t * s * s;
  PRECISE float b2 = 3.0f * t * t * s;
  PRECISE float b3 = t * t * t;
  PRECISE vec3 p = b0 * vec3(p0) + b1 * vec3(p1) + b2 * vec3(p2) + b3 * vec3(p3);
  return p;
}

// Canonical parameter of the side's edge point k (of e) and the patch's own (u, v) there.
float stitchCanonicalParam(IN(StitchPatch) sp, uint s, uint k) {
  uint e = sp.sideSegments[s];
  uint c = (sp.sideFlags[s] & kStitchReversed) != 0u ? e - k : k;
  return exactRatio(c, e);  // the corners exactly: both sides through a corner give its point
}

// Position of the side's edge point k: on a collapsed side the pole itself (a Bernstein sum of
// four equal points need not give that point in fp32).
vec3 stitchSidePosition(IN(StitchPatch) sp, uint s, uint k, IN(vec4) p0, IN(vec4) p1,
                        IN(vec4) p2, IN(vec4) p3) {
  if ((sp.sideFlags[s] & kStitchCollapsed) != 0u) return vec3(p0);
  return stitchEdgePoint(p0, p1, p2, p3, stitchCanonicalParam(sp, s, k));
}

vec2 stitchSideUV(IN(StitchPatch) sp, uint s, uint k) {
  float t = exactRatio(k, sp.sideSegments[s]);
  if (s == 0u) return vec2(t, 0.0f);
  if (s == 1u) return vec2(1.0f, t);
  if (s == 2u) return vec2(t, 1.0f);
  return vec2(0.0f, t);
}

// Where the pattern evaluates local vertex `local`: its (u, v), and the curves it lies on (a
// row, column false: gridCurves at u; or a column, true: at v) with its parameter along them.
// Inner vertices lie on their row, a side's points on the side's own row or column.
struct StitchVertexCurve {
  vec2 uv;
  bool column;
  float fixedParam;
  float along;
};

StitchVertexCurve stitchVertexCurve(IN(StitchPatch) sp, uint local) {
  uint cv = stitchInner(sp.nv);
  uint inner = stitchInner(sp.nu) * cv;
  StitchVertexCurve r;
  if (local < inner) {
    uint i = local / cv;
    r.uv = vec2(stitchInnerParam(i, sp.nu), stitchInnerParam(local - i * cv, sp.nv));
    r.column = false;
    r.fixedParam = r.uv.x;
    r.along = r.uv.y;
    return r;
  }
  uint s = 0u;
  uint k = local - inner;
  while (s < 3u && k > sp.sideSegments[s]) {
    k = k - (sp.sideSegments[s] + 1u);
    s = s + 1u;
  }
  r.uv = stitchSideUV(sp, s, k);
  r.column = (s & 1u) == 0u;
  vec2 end = stitchSideUV(sp, s, 0u);
  r.fixedParam = r.column ? end.y : end.x;
  r.along = r.column ? r.uv.x : r.uv.y;
  return r;
}

#endif
