// Rule T's bounds for one GeneralPatch node: its control points (general_eval.h's
// generalPoint) into gNet (polynomial: as they are, differenced; rational: moved to the first
// control point), restricted to the node, bounded by tolerance_net.h. Separate
// from tolerance_net.h because it reads the control-point buffer, which the C++ mirror holds
// as a member (host/eval/general_mirror.cpp includes this inside its kernel struct).
// Include general_eval.h and tolerance_net.h first.
#ifndef TESSERA_TOLERANCE_GENERAL_H
#define TESSERA_TOLERANCE_GENERAL_H

vec4 generalSecondBounds(IN(GeneralPatch) gp, vec4 rect) {
  int n = int(gp.degreeU);
  int m = int(gp.degreeV);
  gNet.n = n;
  gNet.m = m;
  bool rational = gp.rational != 0u;
  // Rational: P_h − w·P₀₀, the Cartesian part moved to the first control point (w₀₀ > 0), as
  // general_eval.h evaluates; S − P₀₀ has the same derivatives as S.
  vec4 first = generalPoint(gp, 0, 0);
  vec3 origin = rational ? projected(first) : vec3(0.0f);
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
  return rationalNetSecondBounds();
}

#endif
