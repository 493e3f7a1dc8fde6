// Rule T's bounds for one GeneralPatch node: its control points (general_eval.h's
// generalPoint) into gNet.h, restricted to the node, bounded by tolerance_net.h. Separate
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
  for (int i = 0; i < kGeneralMaxOrder; ++i) {
    if (i > n) break;
    for (int j = 0; j < kGeneralMaxOrder; ++j) {
      if (j > m) break;
      gNet.h[i * (m + 1) + j] = generalPoint(gp, i, j);
    }
  }
  restrictDivisionNet(rect);
  return netSecondBounds(gp.rational != 0u);
}

#endif
