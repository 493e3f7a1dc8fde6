// Division counts of rational Bézier patches in fp32: the `split` method of
// host/division/count.h (B1..B8 with ρ ≥ sup β/|w| and σ ≥ sup ω/|w| from q×q de Casteljau
// pieces, the corrected A_ijk; docs/rational_division.md), then Filip's closed-form counts.
// Compiled as GLSL (shaders/division_count.comp.glsl) and as C++
// (host/division/count_mirror.cpp) from this one text. Include shared_glsl_cpp.h and
// layout.h first.
#ifndef TESSERA_DIVISION_COUNT_H
#define TESSERA_DIVISION_COUNT_H

#define DIVISION_MAX_POINTS 64  // (7 + 1)²
#define DIVISION_MAX_DEGREE 7

// The homogeneous net and its degree-keeping derivative nets (eq. D1, D2), c[i*(m+1) + j].
struct DivisionNet {
  int n;
  int m;
  vec4 h[DIVISION_MAX_POINTS];
  vec4 d1u[DIVISION_MAX_POINTS];
  vec4 d1v[DIVISION_MAX_POINTS];
  vec4 d2u[DIVISION_MAX_POINTS];
  vec4 d2v[DIVISION_MAX_POINTS];
  vec4 d11[DIVISION_MAX_POINTS];
};


// Working storage, global so that GLSL passes no 6 KB struct by value (GLSL `in`/`inout` copy):
// private per invocation in GLSL, thread_local in the C++ mirror.
#ifdef __cplusplus
#define DIVISION_STORAGE thread_local
#else
#define DIVISION_STORAGE
#endif
DIVISION_STORAGE DivisionNet gNet;
// The net's degrees as the arithmetic reads them: gNet.n and gNet.m, or constants in a shader
// built for one degree pair (DIVISION_FIXED_DEGREE_U and _V: the quadtree_general_tolerance_*
// variants), where every loop over the net then has a constant trip count and the driver can
// keep the nets in registers instead of indexing memory lane by lane.
#ifdef DIVISION_FIXED_DEGREE_U
#define DIVISION_NET_N DIVISION_FIXED_DEGREE_U
#define DIVISION_NET_M DIVISION_FIXED_DEGREE_V
#else
#define DIVISION_NET_N gNet.n
#define DIVISION_NET_M gNet.m
#endif
// Two loops of the rational path stay loops in those variants: over the pairs of control
// points (divisionClassMaxima: (n+1)²(m+1)² pairs) and over the weight ratios' q × q pieces
// (divisionWeightRatios, a rare path). Unrolled with everything else, they made llvmpipe's
// build of a rational variant take 7–37 s instead of 1–2. (GLSL's [[dont_unroll]]: the shader
// enables GL_EXT_control_flow_attributes; the C++ mirror's variants leave it to the compiler.)
#if defined(DIVISION_FIXED_DEGREE_U) && !defined(__cplusplus)
#define DIVISION_KEEP_LOOP [[dont_unroll]]
#else
#define DIVISION_KEEP_LOOP
#endif
// The scalar nets (w, β, ω) of one piece, packed so that one de Casteljau pass restricts all
// three.
DIVISION_STORAGE vec3 gPiece[DIVISION_MAX_POINTS];

// D = (n−a)(X_(a+1) − X_a) + a(X_a − X_(a−1)) along u (dir 0) or v (dir 1), for the net in
// `which` (0: h, 1: d1u, 2: d1v) into `out` (0: d1u, 1: d1v, 2: d2u, 3: d2v, 4: d11).
vec4 divisionSource(int which, int k) {
  if (which == 0) return gNet.h[k];
  if (which == 1) return gNet.d1u[k];
  return gNet.d1v[k];
}

vec4 degreeKeepingDerivative(int which, int dir, int a, int b) {
  int s = DIVISION_NET_M + 1;
  int deg = dir == 0 ? DIVISION_NET_N : DIVISION_NET_M;
  int idx = dir == 0 ? a : b;
  int step = dir == 0 ? s : 1;
  int k = a * s + b;
  PRECISE vec4 r = vec4(0.0f);
  if (idx < deg) {
    PRECISE vec4 diff = divisionSource(which, k + step) - divisionSource(which, k);
    r = r + float(deg - idx) * diff;
  }
  if (idx > 0) {
    PRECISE vec4 diff = divisionSource(which, k) - divisionSource(which, k - step);
    r = r + float(idx) * diff;
  }
  return r;
}

void divisionDerivativeNets() {
  int s = DIVISION_NET_M + 1;
  for (int a = 0; a <= DIVISION_NET_N; ++a)
    for (int b = 0; b <= DIVISION_NET_M; ++b) {
      gNet.d1u[a * s + b] = degreeKeepingDerivative(0, 0, a, b);
      gNet.d1v[a * s + b] = degreeKeepingDerivative(0, 1, a, b);
    }
  for (int a = 0; a <= DIVISION_NET_N; ++a)
    for (int b = 0; b <= DIVISION_NET_M; ++b) {
      gNet.d2u[a * s + b] = degreeKeepingDerivative(1, 0, a, b);
      gNet.d2v[a * s + b] = degreeKeepingDerivative(2, 1, a, b);
      gNet.d11[a * s + b] = degreeKeepingDerivative(1, 1, a, b);
    }
}

// x.P·y.w − x.w·y.P
vec3 divisionWedge(vec4 x, vec4 y) {
  PRECISE vec3 a = vec3(x) * y.w;
  PRECISE vec3 b = x.w * vec3(y);
  PRECISE vec3 r = a - b;
  return r;
}

float divisionNorm(vec3 v) {
  PRECISE float r = sqrt(dot(v, v));
  return r;
}

// One coefficient row (stride `stride`, `degree` + 1 entries from `first`) of the piece's
// (w, β, ω) nets restricted to [t0, t1]: split at t1 keeping the left part, then at t0/t1
// keeping the right part (de Casteljau), as restrictCoefficients in host/geometry/homogeneous_net.h.
void restrictPieceRow(int first, int stride, int degree, float t0, float t1) {
  vec3 row[DIVISION_MAX_DEGREE + 1];
  vec3 left[DIVISION_MAX_DEGREE + 1];
  for (int k = 0; k <= degree; ++k) row[k] = gPiece[first + k * stride];
  left[0] = row[0];
  PRECISE float om1 = 1.0f - t1;
  for (int r = 1; r <= degree; ++r) {
    for (int k = 0; k <= degree - r; ++k) {
      PRECISE vec3 x = om1 * row[k] + t1 * row[k + 1];
      row[k] = x;
    }
    left[r] = row[0];
  }
  PRECISE float s = t0 / t1;
  PRECISE float om = 1.0f - s;
  for (int k = 0; k <= degree; ++k) row[k] = left[k];
  gPiece[first + degree * stride] = row[degree];
  for (int r = 1; r <= degree; ++r) {
    for (int k = 0; k <= degree - r; ++k) {
      PRECISE vec3 x = om * row[k] + s * row[k + 1];
      row[k] = x;
    }
    gPiece[first + (degree - r) * stride] = row[degree - r];
  }
}

// ρ ≥ sup β/|w| (ratios.x), σ ≥ sup ω/|w| (ratios.y) over q×q pieces; false when some piece's
// w coefficients are not all of one strict sign, or two pieces disagree.
bool divisionWeightRatios(int q, OUT(vec2) ratios) {
  int count = (DIVISION_NET_N + 1) * (DIVISION_NET_M + 1);
  int s = DIVISION_NET_M + 1;
  int qv = DIVISION_NET_M == 0 ? 1 : q;
  int sign = 0;
  ratios = vec2(0.0f, 0.0f);
  DIVISION_KEEP_LOOP for (int pu = 0; pu < q; ++pu)
    DIVISION_KEEP_LOOP for (int pv = 0; pv < qv; ++pv) {
      for (int k = 0; k < count; ++k) {
        float wk = gNet.h[k].w;
        gPiece[k] = vec3(wk, wk == 0.0f ? 1.0f : 0.0f, abs(wk));
      }
      // Exact ends, so the pieces cover [0, 1]² on every driver (u1 = 1 is not restricted).
      float u0 = exactRatio(uint(pu), uint(q));
      float u1 = exactRatio(uint(pu + 1), uint(q));
      float v0 = exactRatio(uint(pv), uint(qv));
      float v1 = exactRatio(uint(pv + 1), uint(qv));
      if (u0 != 0.0f || u1 != 1.0f)
        for (int j = 0; j <= DIVISION_NET_M; ++j) restrictPieceRow(j, s, DIVISION_NET_N, u0, u1);
      if (v0 != 0.0f || v1 != 1.0f)
        for (int i = 0; i <= DIVISION_NET_N; ++i) restrictPieceRow(i * s, 1, DIVISION_NET_M, v0, v1);
      bool positive = true;
      bool negative = true;
      for (int k = 0; k < count; ++k) {
        positive = positive && gPiece[k].x > 0.0f;
        negative = negative && gPiece[k].x < 0.0f;
      }
      int pieceSign = positive ? 1 : (negative ? -1 : 0);
      if (pieceSign == 0 || (sign != 0 && pieceSign != sign)) return false;
      sign = pieceSign;
      for (int k = 0; k < count; ++k) {
        vec3 c = gPiece[k];
        PRECISE float aw = abs(c.x);
        PRECISE float rb = c.y / aw;
        PRECISE float ro = c.z / aw;
        ratios.x = max(ratios.x, rb);
        ratios.y = max(ratios.y, ro);
      }
    }
  return true;
}

// Where the d_k = D1_k.w (along u or along v) of the k index lie: the extreme s_k = d_k/w_k
// of the kept weights, and the (w_k, d_k) box of the vanished ones (host/division/count.cpp,
// classMaxima: the norm is convex in them, so the extremes give the max over k).
struct DivisionKRange {
  float sMin;
  float sMax;
  float wzMin;
  float wzMax;
  float dzMin;
  float dzMax;
  bool anyKept;
  bool anyVanished;
};

DivisionKRange divisionKRange(bool alongU) {
  int count = (DIVISION_NET_N + 1) * (DIVISION_NET_M + 1);
  DivisionKRange r;
  r.sMin = 0.0f;
  r.sMax = 0.0f;
  r.wzMin = 0.0f;
  r.wzMax = 0.0f;
  r.dzMin = 0.0f;
  r.dzMax = 0.0f;
  r.anyKept = false;
  r.anyVanished = false;
  for (int k = 0; k < count; ++k) {
    float wk = gNet.h[k].w;
    float dk = alongU ? gNet.d1u[k].w : gNet.d1v[k].w;
    if (wk == 0.0f) {
      r.wzMin = r.anyVanished ? min(r.wzMin, wk) : wk;
      r.wzMax = r.anyVanished ? max(r.wzMax, wk) : wk;
      r.dzMin = r.anyVanished ? min(r.dzMin, dk) : dk;
      r.dzMax = r.anyVanished ? max(r.dzMax, dk) : dk;
      r.anyVanished = true;
    } else {
      PRECISE float sk = dk / wk;
      r.sMin = r.anyKept ? min(r.sMin, sk) : sk;
      r.sMax = r.anyKept ? max(r.sMax, sk) : sk;
      r.anyKept = true;
    }
  }
  return r;
}

// B1..B8 class maxima of the four numerators (0: uu, 1: uv, 2: vv, 3: uv with u and v
// exchanged, S_vu; docs/rational_division.md), 8 classes each, indexed
// 4·[i vanished] + 2·[j vanished] + [k vanished].
DIVISION_STORAGE float gClass[32];

// One (i, j) of numerator `partial`: A_ijk = E w_k − 2F d_k, maximised over k by the range.
void divisionAccumulate(int partial, vec3 e, vec3 f, float den, int cls, IN(DivisionKRange) r) {
  PRECISE vec3 f2 = 2.0f * f;
  int base = 8 * partial + cls;
  if (r.anyKept) {
    PRECISE float v = max(divisionNorm(e - f2 * r.sMin), divisionNorm(e - f2 * r.sMax));
    PRECISE float q = v / den;
    gClass[base] = max(gClass[base], q);
  }
  if (r.anyVanished) {
    PRECISE float v = 0.0f;
    v = max(v, divisionNorm(e * r.wzMin - f2 * r.dzMin));
    v = max(v, divisionNorm(e * r.wzMin - f2 * r.dzMax));
    v = max(v, divisionNorm(e * r.wzMax - f2 * r.dzMin));
    v = max(v, divisionNorm(e * r.wzMax - f2 * r.dzMax));
    PRECISE float q = v / den;
    gClass[base + 1] = max(gClass[base + 1], q);
  }
}

// All four numerators' class maxima in one pass over the (i, j) pairs (each control-net entry
// is loaded once per pair; the GPU keeps these arrays in scratch memory). A C++ includer that
// defines DIVISION_CLASS_MAXIMA_ELSEWHERE supplies divisionClassMaxima itself (the mirror's
// rule T variants: the same operations four pairs at a time, host/eval/detail/
// division_class_maxima_sse.inc) and keeps this one as divisionClassMaximaScalar.
#ifdef DIVISION_CLASS_MAXIMA_ELSEWHERE
#define DIVISION_CLASS_MAXIMA_SCALAR divisionClassMaximaScalar
void divisionClassMaxima();
#else
#define DIVISION_CLASS_MAXIMA_SCALAR divisionClassMaxima
#endif
void DIVISION_CLASS_MAXIMA_SCALAR() {
  int count = (DIVISION_NET_N + 1) * (DIVISION_NET_M + 1);
  DivisionKRange ru = divisionKRange(true);
  DivisionKRange rv = divisionKRange(false);
  for (int c = 0; c < 32; ++c) gClass[c] = 0.0f;
  DIVISION_KEEP_LOOP for (int i = 0; i < count; ++i) {
    vec4 hi = gNet.h[i];
    vec4 d1ui = gNet.d1u[i];
    vec4 d1vi = gNet.d1v[i];
    vec4 d2ui = gNet.d2u[i];
    vec4 d2vi = gNet.d2v[i];
    vec4 d11i = gNet.d11[i];
    bool vi = hi.w == 0.0f;
    DIVISION_KEEP_LOOP for (int j = 0; j < count; ++j) {
      vec4 hj = gNet.h[j];
      vec4 d1uj = gNet.d1u[j];
      vec4 d1vj = gNet.d1v[j];
      bool vj = hj.w == 0.0f;
      PRECISE float den = (vi ? 1.0f : abs(hi.w)) * (vj ? 1.0f : abs(hj.w));
      int cls = (vi ? 4 : 0) + (vj ? 2 : 0);
      vec3 fu = divisionWedge(d1ui, hj);
      vec3 fv = divisionWedge(d1vi, hj);
      vec3 mixed = divisionWedge(d11i, hj);
      PRECISE vec3 e1 = mixed + divisionWedge(d1ui, d1vj);
      PRECISE vec3 e3 = mixed + divisionWedge(d1vi, d1uj);
      divisionAccumulate(0, divisionWedge(d2ui, hj), fu, den, cls, ru);
      divisionAccumulate(1, e1, fu, den, cls, rv);
      divisionAccumulate(2, divisionWedge(d2vi, hj), fv, den, cls, rv);
      divisionAccumulate(3, e3, fv, den, cls, ru);
    }
  }
}

// Σ_S B_S σ^(3−|S|) ρ^|S| for one numerator (host/division/count.cpp, combineClasses).
float divisionCombine(int partial, float rho, float sigma) {
  PRECISE float sum = 0.0f;
  for (int c = 0; c < 8; ++c) {
    float b = gClass[8 * partial + c];
    if (b == 0.0f) continue;
    int vanished = ((c >> 2) & 1) + ((c >> 1) & 1) + (c & 1);
    PRECISE float term = b;
    for (int t = 0; t < 3 - vanished; ++t) term = term * sigma;
    for (int t = 0; t < vanished; ++t) term = term * rho;
    sum = sum + term;
  }
  return sum;
}

// Filip's closed-form counts (docs/rational_division.md): the smallest real N_u·N_v with
// a/N_u² + 2b/(N_u N_v) + c/N_v² ≤ T, one count held at 1 where the optimum puts it below.
vec2 divisionRealCounts(float a, float b, float c, float tolerance) {
  PRECISE float T = 8.0f * tolerance;
  PRECISE float nu = 1.0f;
  PRECISE float nv = 1.0f;
  PRECISE float lhs = a + 2.0f * b + c;
  if (lhs > T) {
    if (a > 0.0f && c > 0.0f) {
      PRECISE float ratio = sqrt(a / c);
      PRECISE float product = 2.0f * (sqrt(a * c) + b) / T;
      nu = sqrt(product * ratio);
      nv = sqrt(product / ratio);
    } else if (a == 0.0f && c == 0.0f) {
      nu = sqrt(2.0f * b / T);
      nv = nu;
    } else if (c == 0.0f) {
      nv = 0.0f;
    } else {
      nu = 0.0f;
    }
    if (nv < 1.0f) {
      nv = 1.0f;
      PRECISE float rest = T - c;
      nu = (b + sqrt(b * b + a * rest)) / rest;
    } else if (nu < 1.0f) {
      nu = 1.0f;
      PRECISE float rest = T - a;
      nv = (b + sqrt(b * b + c * rest)) / rest;
    }
  }
  return vec2(max(1.0f, nu), max(1.0f, nv));
}

// The whole count for the net loaded into gNet.n, gNet.m, gNet.h.
DivisionResult divisionCounts(IN(DivisionPush) params) {
  DivisionResult res;
  res.nu = params.maxPerDirection;
  res.nv = params.maxPerDirection;
  res.status = kDivisionUnbounded;
  res.realU = 0.0f;
  res.realV = 0.0f;
  res.uu = 0.0f;
  res.uv = 0.0f;
  res.vv = 0.0f;
  int count = (DIVISION_NET_N + 1) * (DIVISION_NET_M + 1);
  bool anyVanished = false;
  bool anyNegative = false;
  bool anyPositive = false;
  for (int k = 0; k < count; ++k) {
    anyVanished = anyVanished || gNet.h[k].w == 0.0f;
    anyNegative = anyNegative || gNet.h[k].w < 0.0f;
    anyPositive = anyPositive || gNet.h[k].w > 0.0f;
  }
  vec2 ratios = vec2(0.0f, 1.0f);
  if (anyVanished || (anyNegative && anyPositive)) {
    if (!divisionWeightRatios(int(params.ratioPieces), ratios)) return res;
  }
  divisionDerivativeNets();
  divisionClassMaxima();
  res.uu = divisionCombine(0, ratios.x, ratios.y);
  if (DIVISION_NET_M > 0) {
    res.uv = min(divisionCombine(1, ratios.x, ratios.y), divisionCombine(3, ratios.x, ratios.y));
    res.vv = divisionCombine(2, ratios.x, ratios.y);
  }
  vec2 real = divisionRealCounts(res.uu, res.uv, res.vv, params.tolerance);
  res.realU = real.x;
  res.realV = real.y;
  res.status = kDivisionOk;
  float cap = float(params.maxPerDirection);
  // Also catches an overflow to infinity (or NaN) in fp32: clamped, reported as capped.
  if (!(real.x <= cap)) {
    res.nu = params.maxPerDirection;
    res.status = kDivisionCapped;
  } else {
    res.nu = uint(ceil(real.x));
  }
  if (!(real.y <= cap)) {
    res.nv = params.maxPerDirection;
    res.status = kDivisionCapped;
  } else {
    res.nv = uint(ceil(real.y));
  }
  return res;
}

#endif
