#include "geometry/closest_point.h"

#include <algorithm>
#include <cmath>

#include "geometry/bezier.h"
#include "geometry/bicubic.h"
#include "geometry/rational.h"

namespace tessera {
namespace {

SurfaceDerivatives derivativesAt(const BezierPatch& patch, glm::dvec2 uv) {
  return patch.degreeU == 3 && patch.degreeV == 3 ? bicubicDerivatives(patch, uv.x, uv.y)
                                                  : patchDerivatives(patch, uv.x, uv.y);
}

glm::dvec2 clampToDomain(glm::dvec2 uv) { return glm::clamp(uv, glm::dvec2(0.0), glm::dvec2(1.0)); }

// The search, with `derivativesAt(uv)` giving at least the partials up to second order.
template <class Derivatives>
ClosestPoint closestPoint(Derivatives derivativesAt, const glm::dvec3& target, glm::dvec2 start,
                          int iterations, double enough) {
  glm::dvec2 uv = clampToDomain(start);
  SurfaceDerivatives d = derivativesAt(uv);
  double best = glm::length(d.p - target);
  double damping = 0.0;
  for (int it = 0; it < iterations && best > enough; ++it) {
    const glm::dvec3 f = d.p - target;
    // Gradient and Hessian of ½|f|².
    const double gu = glm::dot(d.pu, f), gv = glm::dot(d.pv, f);
    double huu = glm::dot(d.pu, d.pu) + glm::dot(d.puu, f);
    double huv = glm::dot(d.pu, d.pv) + glm::dot(d.puv, f);
    double hvv = glm::dot(d.pv, d.pv) + glm::dot(d.pvv, f);
    const double scale = std::max({std::fabs(huu), std::fabs(hvv), 1e-300});
    glm::dvec2 next = uv;
    bool improved = false;
    // Try the Newton step, then more and more damped ones (towards gradient descent).
    for (int attempt = 0; attempt < 8 && !improved; ++attempt) {
      const double a = huu + damping * scale, b = huv, c = hvv + damping * scale;
      const double det = a * c - b * b;
      if (a > 0 && det > 0) {
        const glm::dvec2 step((c * gu - b * gv) / det, (a * gv - b * gu) / det);
        next = clampToDomain(uv - step);
        // Converged: the step no longer moves the parameter measurably (Newton's last steps
        // are tiny), so further damped trials could only waste evaluations.
        if (glm::length(next - uv) < 1e-12) return {uv, d.p, best};
        const SurfaceDerivatives trial = derivativesAt(next);
        const double distance = glm::length(trial.p - target);
        if (distance < best) {
          best = distance;
          uv = next;
          d = trial;
          improved = true;
          damping *= 0.25;
          break;
        }
      }
      damping = damping == 0.0 ? 1e-3 : damping * 10.0;
    }
    if (!improved) break;  // a (local) minimum within the domain, or on its boundary
  }
  return {uv, d.p, best};
}

}  // namespace

// The search reads only the partials up to second order. The patch does not change, so once
// it is known to be valid (checked by the first evaluation, or by the caller) the evaluations
// take the unchecked second-order form at fixed degrees: the same doubles. Checking the patch
// and looping at run-time degrees over partials the search does not read was most of their
// time.
ClosestPoint closestPointOnPatch(const BezierPatch& patch, const glm::dvec3& target,
                                 glm::dvec2 start, int iterations, double enough) {
  const bool fast = patch.weights.empty() && !(patch.degreeU == 3 && patch.degreeV == 3);
  bool checked = false;
  return closestPoint(
      [&](glm::dvec2 uv) {
        if (!fast || !checked) return checked = true, derivativesAt(patch, uv);
        return patchSecondDerivativesOfValid(patch, uv.x, uv.y);
      },
      target, start, iterations, enough);
}

ClosestPoint closestPointOnPatch(const RationalBezierPatch& patch, const glm::dvec3& target,
                                 glm::dvec2 start, int iterations, double enough) {
  bool checked = false;
  return closestPoint(
      [&](glm::dvec2 uv) {
        if (!checked) return checked = true, rationalPatchSecondDerivatives(patch, uv.x, uv.y);
        return rationalPatchSecondDerivativesOfValid(patch, uv.x, uv.y);
      },
      target, start, iterations, enough);
}

ClosestPoint closestPointOnValidPatch(const BezierPatch& patch, const glm::dvec3& target,
                                      glm::dvec2 start, int iterations, double enough) {
  if (!patch.weights.empty() || (patch.degreeU == 3 && patch.degreeV == 3))
    return closestPointOnPatch(patch, target, start, iterations, enough);
  return closestPoint(
      [&](glm::dvec2 uv) { return patchSecondDerivativesOfValid(patch, uv.x, uv.y); }, target,
      start, iterations, enough);
}

ClosestPoint closestPointOnValidPatch(const RationalBezierPatch& patch, const glm::dvec3& target,
                                      glm::dvec2 start, int iterations, double enough) {
  return closestPoint(
      [&](glm::dvec2 uv) { return rationalPatchSecondDerivativesOfValid(patch, uv.x, uv.y); },
      target, start, iterations, enough);
}

}  // namespace tessera
