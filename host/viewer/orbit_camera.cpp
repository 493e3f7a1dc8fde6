#include "viewer/orbit_camera.h"

#include <algorithm>
#include <cmath>

namespace tessera::viewer {

OrbitCamera OrbitCamera::framing(const std::vector<BezierPatch>& patches, double aspect) {
  OrbitCamera orbit;
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const BezierPatch& p : patches)
    for (const glm::dvec3& c : p.cp) {
      lo = glm::min(lo, c);
      hi = glm::max(hi, c);
    }
  if (lo.x > hi.x) lo = hi = glm::dvec3(0.0);  // no patches: any camera shows nothing
  orbit.target = 0.5 * (lo + hi);
  // The sphere about the box's centre through the farthest control point holds the scene
  // (the convex hull property) from every direction the orbit takes.
  double radius = 0;
  for (const BezierPatch& p : patches)
    for (const glm::dvec3& c : p.cp) radius = std::max(radius, glm::length(c - orbit.target));
  orbit.sceneRadius = std::max(radius, 1e-6);
  // It fits the narrower of the two fields of view with a 2% margin.
  const double halfFov = std::atan(std::tan(0.5 * orbit.fovY) * std::min(aspect, 1.0));
  orbit.distance = 1.02 * orbit.sceneRadius / std::sin(halfFov);
  return orbit;
}

glm::dvec3 OrbitCamera::eye() const {
  return target + distance * glm::dvec3(std::cos(pitch) * std::cos(yaw),
                                        std::cos(pitch) * std::sin(yaw), std::sin(pitch));
}

void OrbitCamera::drag(double dx, double dy, int windowWidth) {
  const double radiansPerPixel = 3.14159265358979 / std::max(windowWidth, 1);
  yaw -= dx * radiansPerPixel;
  pitch = std::clamp(pitch + dy * radiansPerPixel, -1.5, 1.5);  // short of the poles: up is +z
}

void OrbitCamera::zoom(double steps) {
  distance = std::clamp(distance * std::pow(0.9, steps), 1e-3 * sceneRadius, 1e3 * sceneRadius);
}

Camera OrbitCamera::camera(int width, int height) const {
  const double nearPlane = std::max(distance - 1.01 * sceneRadius, 2e-3 * sceneRadius);
  const double farPlane = distance + 1.01 * sceneRadius;
  return lookAtCamera(eye(), target, {0, 0, 1}, fovY, width, height, nearPlane, farPlane);
}

glm::vec3 OrbitCamera::lightDirection() const {
  const glm::dvec3 look = glm::normalize(target - eye());
  const glm::dvec3 right = glm::normalize(glm::cross(look, glm::dvec3(0, 0, 1)));
  const glm::dvec3 up = glm::cross(right, look);
  return glm::vec3(glm::normalize(-look + 0.9 * up - 0.9 * right));
}

OrbitCamera orbitPathFrame(const OrbitCamera& start, int frame, int frames) {
  OrbitCamera at = start;
  at.yaw += 2.0 * 3.14159265358979 * double(frame) / double(std::max(frames, 1));
  return at;
}

}  // namespace tessera::viewer
