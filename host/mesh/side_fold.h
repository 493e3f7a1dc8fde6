// A patch side that folds back on itself: its control points lie on one line and the curve
// runs along that line, turns, and runs back over part of the way it came (the teaspoon's
// handle tip: patch 12's side u = 1 has x = −a, +a, 0, 0 at constant y, z, so it goes from −a
// to about +0.25a and back to 0). Over the retraced part the two strands are one curve in
// space: the surface meets itself there, and the mesh must be closed across it.
#pragma once
#include <optional>
#include <vector>

#include "geometry/patch.h"

namespace tessera {

struct SideFold {
  std::vector<double> coordinate;  // the control points' positions along the line (Bernstein)
  std::vector<double> strands;     // 0 = t0 < t1 < … < tk = 1: the turns, s monotone between
};

// The fold of a side with these control points (in increasing t), or none when the points
// are not on one line or the curve's position along it is monotone. Collinear means every
// point within 1e-12 of the polygon's extent of the line: far below what fp32 evaluation
// resolves, so a side that passes is a line to every vertex the mesh can have.
std::optional<SideFold> findSideFold(const std::vector<glm::dvec3>& points);

// The position along the line of the point at t (de Casteljau, exact at t = 0 and 1).
double foldCoordinate(const SideFold& fold, double t);

// The other parameters whose point is the point at t: on every strand that does not hold t
// and whose range of positions holds s(t), the parameter with the same position (bisection
// on the monotone strand, to the last double).
std::vector<double> foldImages(const SideFold& fold, double t, double s);

}  // namespace tessera
