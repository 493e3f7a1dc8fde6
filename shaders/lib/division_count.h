// Division counts of rational Bézier patches in fp32: the `split` method of
// host/division_count.h (B1..B8 with ρ ≥ sup β/|w| and σ ≥ sup ω/|w| from q×q de Casteljau
// pieces, the corrected A_ijk; docs/rational_division.md), then Filip's closed-form counts.
// Compiled as GLSL (shaders/division_count.comp.glsl) and as C++
// (host/mirror/division_mirror.cpp) from this one text. Include shared_glsl_cpp.h and
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

// Scalar nets of β, ω and w restricted to one piece.
struct DivisionScalars {
  float w[DIVISION_MAX_POINTS];
  float beta[DIVISION_MAX_POINTS];
  float omega[DIVISION_MAX_POINTS];
};

// Working storage, global so that GLSL passes no 6 KB struct by value (GLSL `in`/`inout` copy):
// private per invocation in GLSL, thread_local in the C++ mirror.
#ifdef __cplusplus
#define DIVISION_STORAGE thread_local
#else
#define DIVISION_STORAGE
#endif
DIVISION_STORAGE DivisionNet gNet;
DIVISION_STORAGE DivisionScalars gScalars;

// D = (n−a)(X_(a+1) − X_a) + a(X_a − X_(a−1)) along u (dir 0) or v (dir 1), for the net in
// `which` (0: h, 1: d1u, 2: d1v) into `out` (0: d1u, 1: d1v, 2: d2u, 3: d2v, 4: d11).
vec4 divisionSource(int which, int k) {
  if (which == 0) return gNet.h[k];
  if (which == 1) return gNet.d1u[k];
  return gNet.d1v[k];
}

vec4 degreeKeepingDerivative(int which, int dir, int a, int b) {
  int s = gNet.m + 1;
  int deg = dir == 0 ? gNet.n : gNet.m;
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
  int s = gNet.m + 1;
  for (int a = 0; a <= gNet.n; ++a)
    for (int b = 0; b <= gNet.m; ++b) {
      gNet.d1u[a * s + b] = degreeKeepingDerivative(0, 0, a, b);
      gNet.d1v[a * s + b] = degreeKeepingDerivative(0, 1, a, b);
    }
  for (int a = 0; a <= gNet.n; ++a)
    for (int b = 0; b <= gNet.m; ++b) {
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

// One coefficient row (stride `stride`, `degree` + 1 entries from `first`) of the three scalar
// nets restricted to [t0, t1]: split at t1 keeping the left part, then at t0/t1 keeping the
// right part (de Casteljau), as restrictCoefficients in host/homogeneous_net.h.
void restrictScalarRow(int first, int stride, int degree, float t0,
                       float t1) {
  for (int which = 0; which < 3; ++which) {
    float row[DIVISION_MAX_DEGREE + 1];
    float left[DIVISION_MAX_DEGREE + 1];
    for (int k = 0; k <= degree; ++k) {
      int idx = first + k * stride;
      row[k] = which == 0 ? gScalars.w[idx] : (which == 1 ? gScalars.beta[idx] : gScalars.omega[idx]);
    }
    left[0] = row[0];
    PRECISE float om1 = 1.0f - t1;
    for (int r = 1; r <= degree; ++r) {
      for (int k = 0; k <= degree - r; ++k) {
        PRECISE float x = om1 * row[k] + t1 * row[k + 1];
        row[k] = x;
      }
      left[r] = row[0];
    }
    PRECISE float s = t0 / t1;
    PRECISE float om = 1.0f - s;
    for (int k = 0; k <= degree; ++k) row[k] = left[k];
    float outRow[DIVISION_MAX_DEGREE + 1];
    outRow[degree] = row[degree];
    for (int r = 1; r <= degree; ++r) {
      for (int k = 0; k <= degree - r; ++k) {
        PRECISE float x = om * row[k] + s * row[k + 1];
        row[k] = x;
      }
      outRow[degree - r] = row[degree - r];
    }
    for (int k = 0; k <= degree; ++k) {
      int idx = first + k * stride;
      if (which == 0) gScalars.w[idx] = outRow[k];
      else if (which == 1) gScalars.beta[idx] = outRow[k];
      else gScalars.omega[idx] = outRow[k];
    }
  }
}

// ρ ≥ sup β/|w| (ratios.x), σ ≥ sup ω/|w| (ratios.y) over q×q pieces; false when some piece's
// w coefficients are not all of one strict sign, or two pieces disagree.
bool divisionWeightRatios(int q, OUT(vec2) ratios) {
  int count = (gNet.n + 1) * (gNet.m + 1);
  int s = gNet.m + 1;
  int qv = gNet.m == 0 ? 1 : q;
  int sign = 0;
  ratios = vec2(0.0f, 0.0f);
  for (int pu = 0; pu < q; ++pu)
    for (int pv = 0; pv < qv; ++pv) {
      for (int k = 0; k < count; ++k) {
        float wk = gNet.h[k].w;
        gScalars.w[k] = wk;
        gScalars.beta[k] = wk == 0.0f ? 1.0f : 0.0f;
        gScalars.omega[k] = wk == 0.0f ? 0.0f : abs(wk);
      }
      PRECISE float u0 = float(pu) / float(q);
      PRECISE float u1 = float(pu + 1) / float(q);
      PRECISE float v0 = float(pv) / float(qv);
      PRECISE float v1 = float(pv + 1) / float(qv);
      if (u0 != 0.0f || u1 != 1.0f)
        for (int j = 0; j <= gNet.m; ++j) restrictScalarRow(j, s, gNet.n, u0, u1);
      if (v0 != 0.0f || v1 != 1.0f)
        for (int i = 0; i <= gNet.n; ++i) restrictScalarRow(i * s, 1, gNet.m, v0, v1);
      bool positive = true;
      bool negative = true;
      for (int k = 0; k < count; ++k) {
        positive = positive && gScalars.w[k] > 0.0f;
        negative = negative && gScalars.w[k] < 0.0f;
      }
      int pieceSign = positive ? 1 : (negative ? -1 : 0);
      if (pieceSign == 0 || (sign != 0 && pieceSign != sign)) return false;
      sign = pieceSign;
      for (int k = 0; k < count; ++k) {
        PRECISE float aw = abs(gScalars.w[k]);
        PRECISE float rb = gScalars.beta[k] / aw;
        PRECISE float ro = gScalars.omega[k] / aw;
        ratios.x = max(ratios.x, rb);
        ratios.y = max(ratios.y, ro);
      }
    }
  return true;
}

// The B1..B8 class maxima of one second partial (0: uu, 1: uv, 2: vv, 3: uv with u and v
// exchanged in the numerator, S_vu), combined with ρ and σ:
// Σ_S B_S σ^(3−|S|) ρ^|S| (host/division_count.cpp, classMaxima and combineClasses).
float divisionPartialBound(int partial, float rho, float sigma) {
  int count = (gNet.n + 1) * (gNet.m + 1);
  float sMin = 0.0f, sMax = 0.0f, wzMin = 0.0f, wzMax = 0.0f, dzMin = 0.0f, dzMax = 0.0f;
  bool anyKept = false;
  bool anyVanished = false;
  for (int k = 0; k < count; ++k) {
    float wk = gNet.h[k].w;
    float dk = partial == 0 || partial == 3 ? gNet.d1u[k].w : gNet.d1v[k].w;
    if (wk == 0.0f) {
      wzMin = anyVanished ? min(wzMin, wk) : wk;
      wzMax = anyVanished ? max(wzMax, wk) : wk;
      dzMin = anyVanished ? min(dzMin, dk) : dk;
      dzMax = anyVanished ? max(dzMax, dk) : dk;
      anyVanished = true;
    } else {
      PRECISE float sk = dk / wk;
      sMin = anyKept ? min(sMin, sk) : sk;
      sMax = anyKept ? max(sMax, sk) : sk;
      anyKept = true;
    }
  }
  float b[8];
  for (int c = 0; c < 8; ++c) b[c] = 0.0f;
  for (int i = 0; i < count; ++i)
    for (int j = 0; j < count; ++j) {
      bool mixed = partial == 1 || partial == 3;
      vec4 second = partial == 0 ? gNet.d2u[i] : (mixed ? gNet.d11[i] : gNet.d2v[i]);
      PRECISE vec3 e = divisionWedge(second, gNet.h[j]);
      if (partial == 1) e = e + divisionWedge(gNet.d1u[i], gNet.d1v[j]);
      if (partial == 3) e = e + divisionWedge(gNet.d1v[i], gNet.d1u[j]);
      vec4 first = partial == 2 || partial == 3 ? gNet.d1v[i] : gNet.d1u[i];
      PRECISE vec3 f = divisionWedge(first, gNet.h[j]);
      bool vi = gNet.h[i].w == 0.0f;
      bool vj = gNet.h[j].w == 0.0f;
      PRECISE float den = (vi ? 1.0f : abs(gNet.h[i].w)) * (vj ? 1.0f : abs(gNet.h[j].w));
      int cls = (vi ? 4 : 0) + (vj ? 2 : 0);
      PRECISE vec3 f2 = 2.0f * f;
      if (anyKept) {
        PRECISE float v = max(divisionNorm(e - f2 * sMin), divisionNorm(e - f2 * sMax));
        PRECISE float r = v / den;
        b[cls] = max(b[cls], r);
      }
      if (anyVanished) {
        PRECISE float v = 0.0f;
        v = max(v, divisionNorm(e * wzMin - f2 * dzMin));
        v = max(v, divisionNorm(e * wzMin - f2 * dzMax));
        v = max(v, divisionNorm(e * wzMax - f2 * dzMin));
        v = max(v, divisionNorm(e * wzMax - f2 * dzMax));
        PRECISE float r = v / den;
        b[cls + 1] = max(b[cls + 1], r);
      }
    }
  PRECISE float sum = 0.0f;
  for (int c = 0; c < 8; ++c) {
    if (b[c] == 0.0f) continue;
    int vanished = ((c >> 2) & 1) + ((c >> 1) & 1) + (c & 1);
    PRECISE float term = b[c];
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
  int count = (gNet.n + 1) * (gNet.m + 1);
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
  res.uu = divisionPartialBound(0, ratios.x, ratios.y);
  if (gNet.m > 0) {
    res.uv = min(divisionPartialBound(1, ratios.x, ratios.y),
                 divisionPartialBound(3, ratios.x, ratios.y));
    res.vv = divisionPartialBound(2, ratios.x, ratios.y);
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
