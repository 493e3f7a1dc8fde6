// Rule T's bounds for one GeneralPatch node: its control points (general_eval.h's
// generalPoint) into gNet (polynomial: as they are, differenced; rational: moved to the first
// control point), restricted to the node, bounded by tolerance_net.h. Separate
// from tolerance_net.h because it reads the control-point buffer, which the C++ mirror holds
// as a member (host/eval/general_mirror.cpp includes this inside its kernel struct).
// Include general_eval.h and tolerance_net.h first.
#ifndef TESSERA_TOLERANCE_GENERAL_H
#define TESSERA_TOLERANCE_GENERAL_H

ToleranceTerms generalSecondBounds(IN(GeneralPatch) gp, vec4 rect) {
  gNet.n = int(gp.degreeU);
  gNet.m = int(gp.degreeV);
  int n = DIVISION_NET_N;
  int m = DIVISION_NET_M;
#if defined(DIVISION_FIXED_POLYNOMIAL)
  const bool rational = false;  // a variant for polynomial patches only: the rational path goes
#elif defined(DIVISION_FIXED_RATIONAL)
  const bool rational = true;  // a variant for rational patches only
#else
  bool rational = gp.rational != 0u;
#endif
  // Rational: P_h − w·O, the Cartesian part moved to O, the control point of largest weight
  // (the first of equals; none if no weight is > 0): S − O has the same derivatives as S. Not
  // simply P₀₀: a screen-space patch (screen_tolerance.h) may have w₀₀ ≤ 0, or w₀₀ near 0 and
  // P₀₀ far off.
  vec3 origin = vec3(0.0f);
  if (rational) {
    float heaviest = 0.0f;
    for (int k = 0; k < kGeneralMaxOrder * kGeneralMaxOrder; ++k) {
      if (k >= (n + 1) * (m + 1)) break;
      vec4 c = generalPoint(gp, k / (m + 1), k % (m + 1));
      if (c.w > heaviest) {
        heaviest = c.w;
        origin = projected(c);
      }
    }
  }
  for (int i = 0; i < kGeneralMaxOrder; ++i) {
    if (i > n) break;
    for (int j = 0; j < kGeneralMaxOrder; ++j) {
      if (j > m) break;
      vec4 c = generalPoint(gp, i, j);
      if (rational) {
        PRECISE vec3 rel = vec3(c) - c.w * origin;
        gNet.h[i * (m + 1) + j] = vec4(rel, c.w);
      } else {
        gNet.d1u[i * (m + 1) + j] = c;
      }
    }
  }
  if (!rational) return polynomialNetSecondBounds(rect);
  restrictDivisionNet(rect);
  return toleranceTermsOf(rationalNetSecondBounds());
}

#endif
