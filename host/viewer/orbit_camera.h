// The viewer's camera: it circles the scene's centre (z up, as the teapot stands), turned by
// dragging the mouse and moved nearer or farther by the wheel; the scripted path turns it
// once around the scene at a fixed height.
#pragma once
#include <glm/glm.hpp>

#include <vector>

#include "division/view_dependent.h"
#include "geometry/patch.h"

namespace tessera::viewer {

struct OrbitCamera {
  glm::dvec3 target{0.0};
  double sceneRadius = 1.0;  // of a sphere about target holding every control point
  double yaw = 0.6;          // radians about +z, from +x
  double pitch = 0.45;       // radians above the xy plane
  double distance = 4.0;     // eye to target
  double fovY = 0.7;         // radians

  // Frames `patches` (a sphere holding their control points) from the front right, above.
  static OrbitCamera framing(const std::vector<BezierPatch>& patches, double aspect);

  glm::dvec3 eye() const;
  // Drag by (dx, dy) pixels: a full window width turns half a circle.
  void drag(double dx, double dy, int windowWidth);
  // Wheel steps: each brings the eye 10% nearer (negative: farther).
  void zoom(double steps);
  // The tessellator's and the renderer's camera for a width×height viewport; the near plane
  // hugs the scene's sphere (no nearer than 0.2% of its radius when the eye is inside).
  Camera camera(int width, int height) const;
  // The unit direction towards the key light: upper left, behind the viewer (as
  // tessera render lights its pictures).
  glm::vec3 lightDirection() const;
};

// Frame `frame` of `frames` on the scripted orbit: `start` turned by a full circle in equal steps.
OrbitCamera orbitPathFrame(const OrbitCamera& start, int frame, int frames);

}  // namespace tessera::viewer
