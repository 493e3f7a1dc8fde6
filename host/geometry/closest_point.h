// The point of a Bézier patch closest to a given point, by damped Newton from a starting
// parameter. Used to measure geometric deviation: the parametric metric (deviation.h) compares
// a triangle point with the surface at the same (u, v) mix, which overstates the error where
// the parametrisation is uneven (at a collapsed edge most of a triangle's (u, v) mix crowds
// towards the pole while its position does not).
#pragma once
#include <glm/glm.hpp>

#include "geometry/patch.h"

namespace tessera {

struct ClosestPoint {
  glm::dvec2 uv;
  glm::dvec3 point;
  double distance = 0;
};

// Minimises |S(u, v) − target| over [0,1]² from `start`: Newton on ½|S − target|² with the
// full Hessian, Levenberg damping when it is not positive definite, steps clamped to the
// domain, and never an uphill step — so the result is at most |S(start) − target| and always
// an upper bound of the true distance to the patch. A local search: from a good start (the
// parametric guess) it finds the nearby foot point, not necessarily the global one.
// `enough` > 0 ends the search once the distance is at most `enough` (each step only lowers it,
// so the full search would end at most there too): for a caller that only asks whether the
// distance is within a bound; otherwise the result is the same.
ClosestPoint closestPointOnPatch(const BezierPatch& patch, const glm::dvec3& target,
                                 glm::dvec2 start, int iterations = 12, double enough = 0.0);
// The same for a patch already in homogeneous form: toRationalPatch(patch) gives the same
// result bit for bit, without converting the patch at every step.
ClosestPoint closestPointOnPatch(const RationalBezierPatch& patch, const glm::dvec3& target,
                                 glm::dvec2 start, int iterations = 12, double enough = 0.0);
// The same for a patch that passed validateTessellationPatch (general_patch.h), or its
// homogeneous form: the same result, without checking the patch at every evaluation
// (FaceSurface::distance, the gap refinement's searches).
ClosestPoint closestPointOnValidPatch(const BezierPatch& patch, const glm::dvec3& target,
                                      glm::dvec2 start, int iterations = 12, double enough = 0.0);
ClosestPoint closestPointOnValidPatch(const RationalBezierPatch& patch, const glm::dvec3& target,
                                      glm::dvec2 start, int iterations = 12, double enough = 0.0);

}  // namespace tessera
