// Quad-tree node classification in fp32 (Moriyama & Harada, "Subdivision of bicubic Bézier
// patches by a quad-tree"): find the node's split point by rule B, C or D, evaluate the four
// corners and the split point, run the edge-linearity and flatness tests, decide leaf or split.
// Rule T (tolerance) decides by the proven bound of tolerance_bound.h instead, without frames.
// Compiled as GLSL (shaders/quadtree.comp.glsl) and as C++ (host/quadtree/classify_mirror.cpp)
// from this one text. Include shared_glsl_cpp.h, layout.h, bicubic_eval.h and
// tolerance_bound.h (and for general patches general_eval.h, division_count.h,
// tolerance_net.h and tolerance_general.h) first.
#ifndef TESSERA_QUADTREE_CLASSIFY_H
#define TESSERA_QUADTREE_CLASSIFY_H

// The patch type and its evaluation. Bicubic by default; quadtree_general.comp.glsl and
// host/eval/general_mirror.cpp define these for GeneralPatch (general_eval.h) first, so one
// text classifies both and the bicubic shader is the very same code as before.
#ifndef CLASSIFY_PATCH
#define CLASSIFY_PATCH BicubicPatch
#define CLASSIFY_EVAL evalBicubic
#define CLASSIFY_SCALE bicubicScale
#define CLASSIFY_SECOND_BOUNDS bicubicSecondBounds
#endif

// Position, unit tangents along u and v (zero where the derivative vanishes, as along a
// collapsed edge) and unit normal (zero where none exists) at one point.
struct FrameSample {
  vec3 p;
  vec3 tu;
  vec3 tv;
  vec3 n;
  float kappa;
};

vec3 unitOrZero(vec3 v, float tol) {
  PRECISE float len = sqrt(dot(v, v));
  if (len > tol) return scaleToUnit(v, len);
  return vec3(0.0f);
}

FrameSample frameAt(IN(CLASSIFY_PATCH) bp, float u, float v, float scale, float eps) {
  BicubicDerivs d = CLASSIFY_EVAL(bp, u, v);
  PRECISE float tolArea = eps * scale * scale;
  PRECISE float tolLength = eps * scale;
  FrameSample f;
  f.p = d.p;
  f.tu = unitOrZero(d.pu, tolLength);
  f.tv = unitOrZero(d.pv, tolLength);
  f.n = bicubicNormal(d, u, v, tolArea);
  f.kappa = bicubicKappa(d, f.n, tolArea);
  return f;
}

float kappaAt(IN(CLASSIFY_PATCH) bp, float u, float v, float scale, float eps) {
  BicubicDerivs d = CLASSIFY_EVAL(bp, u, v);
  PRECISE float tol = eps * scale * scale;
  vec3 n = bicubicNormal(d, u, v, tol);
  return bicubicKappa(d, n, tol);
}

// 1 − a·b for two unit directions; 0 when either is missing: a collapsed edge or a point
// without a normal has no direction to disagree with.
float angleTest(vec3 a, vec3 b) {
  if (dot(a, a) == 0.0f || dot(b, b) == 0.0f) return 0.0f;
  PRECISE float t = 1.0f - dot(a, b);
  return t;
}

// Height of the triangle (a, b, c) over its longest side: 2·area / longest side (0 when all
// three are one point).
float triangleHeight(vec3 a, vec3 b, vec3 c) {
  PRECISE vec3 ab = b - a;
  PRECISE vec3 ac = c - a;
  PRECISE vec3 bc = c - b;
  PRECISE vec3 n = cross(ab, ac);
  PRECISE float twiceArea = sqrt(dot(n, n));
  PRECISE float longest = sqrt(max(dot(ab, ab), max(dot(ac, ac), dot(bc, bc))));
  if (!(longest > 0.0f)) return 0.0f;
  PRECISE float h = twiceArea / longest;
  return h;
}

// Whether fp32 resolves a node's children on the model (kResolvedWidthUlps): its width, the
// highest of the triangles from the split point s to consecutive corners, against the unit in
// the last place of its largest coordinate m (2^-23·m, within a factor 2). Scale-free: both
// sides scale with the model, and the width is taken in units of m, so that its squares
// neither underflow for a tiny model nor overflow for a huge one.
bool resolvesChildren(vec3 s, vec3 c0, vec3 c1, vec3 c2, vec3 c3) {
  PRECISE vec3 m3 = max(max(abs(s), abs(c0)), max(max(abs(c1), abs(c2)), abs(c3)));
  PRECISE float m = max(m3.x, max(m3.y, m3.z));
  if (!(m > 0.0f)) return false;
  PRECISE float inv = 1.0f / m;
  PRECISE vec3 a = s * inv;
  PRECISE vec3 b0 = c0 * inv;
  PRECISE vec3 b1 = c1 * inv;
  PRECISE vec3 b2 = c2 * inv;
  PRECISE vec3 b3 = c3 * inv;
  PRECISE float width = max(max(triangleHeight(a, b0, b1), triangleHeight(a, b1, b2)),
                            max(triangleHeight(a, b2, b3), triangleHeight(a, b3, b0)));
  return width >= kResolvedWidthUlps * 1.1920929e-7f;
}

// Node-local coordinates (s, t) ∈ [0,1]² to patch parameters.
float lerpParam(float lo, float hi, float s) {
  PRECISE float r = lo + (hi - lo) * s;
  return r;
}

float kappaAtLocal(IN(CLASSIFY_PATCH) bp, vec4 rect, float s, float t, float scale, float eps) {
  return kappaAt(bp, lerpParam(rect.x, rect.z, s), lerpParam(rect.y, rect.w, t), scale, eps);
}

// Rule C: the largest κ on an S×S grid of interior points (s, t) = ((a+1)/(S+1), (b+1)/(S+1)).
// Returns (s, t, κ); ties keep the first in scan order. Also returns the runner-up, a second
// seed for rule D.
void sampledMaxima(IN(CLASSIFY_PATCH) bp, vec4 rect, int samples, float scale, float eps,
                   OUT(vec3) best, OUT(vec3) second) {
  best = vec3(0.5f, 0.5f, -1.0f);
  second = vec3(0.5f, 0.5f, -1.0f);
  for (int a = 0; a < samples; ++a) {
    for (int b = 0; b < samples; ++b) {
      PRECISE float s = float(a + 1) / float(samples + 1);
      PRECISE float t = float(b + 1) / float(samples + 1);
      float k = kappaAtLocal(bp, rect, s, t, scale, eps);
      if (k > best.z) {
        second = best;
        best = vec3(s, t, k);
      } else if (k > second.z) {
        second = vec3(s, t, k);
      }
    }
  }
}

// The k-th point of rule D's finite-difference stencil around the origin, in units of the
// gradient step (k = 0..3: ±s, ±t) and of the Hessian step (k = 4..11).
vec2 stencilOffset(int k) {
  if (k == 0) return vec2(1.0f, 0.0f);
  if (k == 1) return vec2(-1.0f, 0.0f);
  if (k == 2) return vec2(0.0f, 1.0f);
  if (k == 3) return vec2(0.0f, -1.0f);
  if (k == 4) return vec2(1.0f, 0.0f);
  if (k == 5) return vec2(-1.0f, 0.0f);
  if (k == 6) return vec2(0.0f, 1.0f);
  if (k == 7) return vec2(0.0f, -1.0f);
  if (k == 8) return vec2(1.0f, 1.0f);
  if (k == 9) return vec2(1.0f, -1.0f);
  if (k == 10) return vec2(-1.0f, 1.0f);
  return vec2(-1.0f, -1.0f);
}

// One step of rule D's trust-region searches from x (where κ = kx) to the trial point y: taken
// if κ grows there, and the radius doubles (at most 0.25); else the radius shrinks to a quarter.
void trustRegionStep(IN(CLASSIFY_PATCH) bp, vec4 rect, vec2 y, float scale, float eps,
                     INOUT(vec2) x, INOUT(float) kx, INOUT(float) radius) {
  float ky = kappaAtLocal(bp, rect, y.x, y.y, scale, eps);
  if (ky > kx) {
    x = y;
    kx = ky;
    PRECISE float grown = min(2.0f * radius, 0.25f);
    radius = grown;
  } else {
    PRECISE float shrunk = 0.25f * radius;
    radius = shrunk;
  }
}

// Rule D's interior search: Newton on κu = κv = 0 in node-local coordinates from `seed`,
// gradient by central differences (step 1e-3 of the node), Hessian by a coarser stencil
// (step 2e-2: fp32 second differences at 1e-3 would be mostly rounding noise). Where the
// Hessian is not negative definite it steps along the gradient instead. A trust radius
// (starting at half the sample spacing) bounds each step; a step is taken only if κ grows,
// else the radius shrinks — so the search climbs monotonically and never leaves a sharp
// peak the quadratic model overshoots.
vec3 newtonMaximum(IN(CLASSIFY_PATCH) bp, vec4 rect, vec3 seed, int samples, float scale,
                   float eps) {
  const float hg = 1e-3f;
  const float hh = 2e-2f;
  PRECISE vec2 x = vec2(seed.x, seed.y);
  PRECISE float kx = seed.z;
  PRECISE float radius = 0.5f / float(samples + 1);
  for (int it = 0; it < kNewtonIterations; ++it) {
    float kv[12];
    for (int k = 0; k < 12; ++k) {
      PRECISE float h = k < 4 ? hg : hh;
      vec2 o = stencilOffset(k);
      PRECISE float s = x.x + h * o.x;
      PRECISE float t = x.y + h * o.y;
      kv[k] = kappaAtLocal(bp, rect, s, t, scale, eps);
    }
    PRECISE float gs = (kv[0] - kv[1]) / (2.0f * hg);
    PRECISE float gt = (kv[2] - kv[3]) / (2.0f * hg);
    PRECISE float hss = (kv[4] - 2.0f * kx + kv[5]) / (hh * hh);
    PRECISE float htt = (kv[6] - 2.0f * kx + kv[7]) / (hh * hh);
    PRECISE float hst = (kv[8] - kv[9] - kv[10] + kv[11]) / (4.0f * hh * hh);
    PRECISE float det = hss * htt - hst * hst;
    PRECISE vec2 step = vec2(gs, gt);
    if (hss < 0.0f && det > 0.0f) {
      step = vec2(-(htt * gs - hst * gt) / det, -(hss * gt - hst * gs) / det);
    }
    PRECISE float slen = sqrt(dot(step, step));
    if (slen > radius) step = step * (radius / slen);
    PRECISE vec2 y = clamp(x + step, vec2(0.0f), vec2(1.0f));
    trustRegionStep(bp, rect, y, scale, eps, x, kx, radius);
  }
  return vec3(x.x, x.y, kx);
}

// Rule D's boundary search: the best of S samples on each edge, refined along that edge by
// the same trust-region Newton in one dimension.
vec3 boundaryMaximum(IN(CLASSIFY_PATCH) bp, vec4 rect, int samples, float scale, float eps) {
  vec3 best = vec3(0.5f, 0.5f, -1.0f);
  int bestEdge = 0;
  for (int e = 0; e < 4; ++e) {
    for (int a = 0; a < samples; ++a) {
      PRECISE float r = float(a + 1) / float(samples + 1);
      PRECISE float s = e == 0 ? r : (e == 1 ? 1.0f : (e == 2 ? r : 0.0f));
      PRECISE float t = e == 0 ? 0.0f : (e == 1 ? r : (e == 2 ? 1.0f : r));
      float k = kappaAtLocal(bp, rect, s, t, scale, eps);
      if (k > best.z) {
        best = vec3(s, t, k);
        bestEdge = e;
      }
    }
  }
  const float hg = 1e-3f;
  const float hh = 2e-2f;
  bool alongS = bestEdge == 0 || bestEdge == 2;
  PRECISE vec2 dir = alongS ? vec2(1.0f, 0.0f) : vec2(0.0f, 1.0f);
  PRECISE vec2 x = vec2(best.x, best.y);
  PRECISE float kx = best.z;
  PRECISE float radius = 0.5f / float(samples + 1);
  for (int it = 0; it < kNewtonIterations; ++it) {
    float kgp = kappaAtLocal(bp, rect, x.x + hg * dir.x, x.y + hg * dir.y, scale, eps);
    float kgm = kappaAtLocal(bp, rect, x.x - hg * dir.x, x.y - hg * dir.y, scale, eps);
    float khp = kappaAtLocal(bp, rect, x.x + hh * dir.x, x.y + hh * dir.y, scale, eps);
    float khm = kappaAtLocal(bp, rect, x.x - hh * dir.x, x.y - hh * dir.y, scale, eps);
    PRECISE float g = (kgp - kgm) / (2.0f * hg);
    PRECISE float h2 = (khp - 2.0f * kx + khm) / (hh * hh);
    PRECISE float step = h2 < 0.0f ? -g / h2 : g;
    step = clamp(step, -radius, radius);
    PRECISE vec2 y = clamp(x + step * dir, vec2(0.0f), vec2(1.0f));
    trustRegionStep(bp, rect, y, scale, eps, x, kx, radius);
  }
  return vec3(x.x, x.y, kx);
}

// The split point of a node in node-local coordinates (s, t), kept kSplitMargin away from the
// edges. Where κ vanishes everywhere sampled (a plane, a degenerate patch) rules C and D fall
// back to the midpoint.
vec2 splitPointLocal(IN(CLASSIFY_PATCH) bp, vec4 rect, uint rule, int samples, float scale,
                     float eps) {
  if (rule == kSplitRuleMidpoint) return vec2(0.5f);
#ifdef CLASSIFY_MIDPOINT_ONLY
  // A rule-B-only shader (quadtree_midpoint.comp.glsl) is never run for another rule; leaving
  // the searches out spares the driver compiling them.
  return vec2(0.5f);
#else
  vec3 best;
  vec3 second;
  sampledMaxima(bp, rect, samples, scale, eps, best, second);
  if (rule == kSplitRuleTrueMax) {
    vec3 a = newtonMaximum(bp, rect, best, samples, scale, eps);
    vec3 b = newtonMaximum(bp, rect, second, samples, scale, eps);
    vec3 c = boundaryMaximum(bp, rect, samples, scale, eps);
    if (a.z > best.z) best = a;
    if (b.z > best.z) best = b;
    if (c.z > best.z) best = c;
  }
  if (!(best.z > 0.0f)) return vec2(0.5f);
  return clamp(vec2(best.x, best.y), vec2(kSplitMargin), vec2(1.0f - kSplitMargin));
#endif
}

NodeDecision classifyNode(IN(CLASSIFY_PATCH) bp, IN(QuadNode) node, uint rule, int samples,
                          IN(ClassifyPush) params) {
#ifdef CLASSIFY_TOLERANCE_ONLY
  // A rule-T-only shader (quadtree_tolerance.comp.glsl) is never run for another rule: the
  // frames and rules B-D below are left out, sparing the driver compiling them.
  return toleranceDecision(CLASSIFY_SECOND_BOUNDS(bp, node.rect), node, params);
#else
#ifndef CLASSIFY_MIDPOINT_ONLY
  // Rule T needs no corner frames: its bound comes from the node's restricted control net.
  if (rule == kSplitRuleTolerance)
    return toleranceDecision(CLASSIFY_SECOND_BOUNDS(bp, node.rect), node, params);
#endif
  PRECISE float scale = CLASSIFY_SCALE(bp);
  float eps = params.degenerateEps;
  vec4 r = node.rect;
  vec2 local = splitPointLocal(bp, r, rule, samples, scale, eps);
  float us = lerpParam(r.x, r.z, local.x);
  float vs = lerpParam(r.y, r.w, local.y);

  // Corners counter-clockwise in (u, v): c0 = (u0,v0), c1 = (u1,v0), c2 = (u1,v1), c3 = (u0,v1).
  FrameSample c0 = frameAt(bp, r.x, r.y, scale, eps);
  FrameSample c1 = frameAt(bp, r.z, r.y, scale, eps);
  FrameSample c2 = frameAt(bp, r.z, r.w, scale, eps);
  FrameSample c3 = frameAt(bp, r.x, r.w, scale, eps);
  FrameSample sp = frameAt(bp, us, vs, scale, eps);

  // Edge linearity: the edge's own tangent at both of its corners.
  PRECISE float lin = angleTest(c0.tu, c1.tu);
  lin = max(lin, angleTest(c1.tv, c2.tv));
  lin = max(lin, angleTest(c3.tu, c2.tu));
  lin = max(lin, angleTest(c0.tv, c3.tv));
  // Flatness: adjacent corners, then every corner against the split point.
  PRECISE float flatness = angleTest(c0.n, c1.n);
  flatness = max(flatness, angleTest(c1.n, c2.n));
  flatness = max(flatness, angleTest(c2.n, c3.n));
  flatness = max(flatness, angleTest(c3.n, c0.n));
  flatness = max(flatness, angleTest(c0.n, sp.n));
  flatness = max(flatness, angleTest(c1.n, sp.n));
  flatness = max(flatness, angleTest(c2.n, sp.n));
  flatness = max(flatness, angleTest(c3.n, sp.n));

  NodeDecision d;
  d.split = vec4(us, vs, sp.kappa, 0.0f);
  d.linearity = lin;
  d.flatness = flatness;
  d.pad = 0u;
  if (lin < params.linearity && flatness < params.flatness) {
    d.cause = kCauseFlat;
  } else if (node.level >= params.maxDepth) {
    d.cause = kCauseMaxDepth;
  } else if (min(r.z - r.x, r.w - r.y) < params.minSize ||
             !resolvesChildren(sp.p, c0.p, c1.p, c2.p, c3.p)) {
    d.cause = kCauseMinSize;
  } else {
    d.cause = kCauseSplit;
  }
  return d;
#endif  // CLASSIFY_TOLERANCE_ONLY
}

#endif
