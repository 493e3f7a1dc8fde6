// Principal curvatures and directions, K, H and the splitting scalar κ of docs/conventions.md.
#pragma once
#include "geometry/patch.h"

namespace tessera {

struct SurfaceCurvature {
  bool degenerate = false;  // |Pu × Pv| ≤ ε·L²: every field below is 0
  double gaussian = 0.0;    // K = (LN − M²)/(EG − F²)
  double mean = 0.0;        // H = (EN − 2FM + GL)/(2(EG − F²)), sign w.r.t. n = Pu × Pv
  double k1 = 0.0;          // H + √max(H² − K, 0), the larger principal curvature
  double k2 = 0.0;          // H − √max(H² − K, 0)
  glm::dvec3 dir1{0.0};     // unit tangent of k1
  glm::dvec3 dir2{0.0};     // unit tangent of k2, = n × dir1
  double kappa = 0.0;       // max(|k1|, |k2|) = |H| + √max(H² − K, 0)
};

// L is the length scale of the degeneracy test (controlNetDiagonal), eps as for unitNormal.
SurfaceCurvature surfaceCurvature(const SurfaceDerivatives& d, double L, double eps = 1e-12);

}  // namespace tessera
