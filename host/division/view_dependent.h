// View-dependent division counts: control points go to homogeneous clip space through the
// camera's view-projection matrix, then to pixels through the viewport, so that TOL is in
// pixels and the counts drive a uniform grid per patch (rule A). In clip space the weight of a
// control point is its depth along the view direction: 0 on the eye plane, < 0 behind the eye.
// Zero weights are what the split bound (division_count.h) exists for; negative ones are
// handled by its σ factor; a patch with every control point at or behind the near plane is
// culled (its convex hull is, so the patch is); a patch that the eye plane cuts has an
// unbounded image and is counted by the subdivided bound over its visible part only.
#pragma once
#include <glm/glm.hpp>

#include <vector>

#include "division/count.h"
#include "mesh/mesh.h"
#include "geometry/patch.h"

namespace tessera {

struct Camera {
  // Clip from world, Vulkan conventions (glm::perspectiveRH_ZO): visible where −w ≤ x, y ≤ w,
  // 0 ≤ z ≤ w; w_clip is the depth in front of the eye.
  glm::dmat4 viewProjection{1.0};
  int width = 1024;  // viewport in pixels
  int height = 1024;
  double nearW = 0.01;  // w_clip on the near plane (the near distance for perspectiveRH_ZO)
};

// A perspective camera at `eye` looking at `target` (vertical field of view in radians).
Camera lookAtCamera(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up,
                    double fovY, int width, int height, double nearDistance = 0.01,
                    double farDistance = 1000.0);

// The patch in screen-space homogeneous coordinates (x_px·w, y_px·w, 0, w), x_px = (x/w + 1)/2
// · width: a rational patch whose projection is the patch's image in pixels. Weights with
// |w| ≤ snap · max|w| become exactly 0 (a control point on the eye plane up to rounding).
RationalBezierPatch screenSpacePatch(const RationalBezierPatch& world, const Camera& camera,
                                     double snap = 1e-12);
// The same for `count` homogeneous points into `screen` (no allocation: the real-time path
// transforms every patch every frame).
void screenSpacePoints(const glm::dvec4* world, size_t count, const Camera& camera,
                       glm::dvec4* screen, double snap = 1e-12);

// Counts for one patch seen by `camera`, TOL = options.tolerance pixels. Culled (counts 0)
// when every control point has w_clip ≤ nearW. When the method finds the image unbounded (the
// eye plane cuts the patch, or touches it at a corner) the subdivided bound with near-plane
// and viewport clipping gives the counts instead and `eyePlaneFallback` is set.
struct ViewDivisions {
  Divisions divisions;
  bool eyePlaneFallback = false;
};
ViewDivisions viewDivisions(const RationalBezierPatch& world, const Camera& camera,
                            const DivisionOptions& options);

// Rule A with per-patch counts: each patch's N_u×N_v grid comes from the quad-tree's rule A
// (buildQuadtree, host/quadtree/quadtree.h) and is triangulated by triangulateLeaves (two triangles per
// cell along the (u_i, v_j)–(u_i+1, v_j+1) diagonal, the triangles division_deviation.h
// measures; fans where a neighbour's finer grid meets a shared edge, so the mesh stays
// watertight). Positions in world coordinates with uvs and patch ids; culled patches (nu = 0)
// emit nothing. Throws std::invalid_argument if the counts do not match the patches or a
// world-space weight is ≤ 0.
TriangleMesh uniformGridMesh(const std::vector<RationalBezierPatch>& patches,
                             const std::vector<Divisions>& counts);

}  // namespace tessera
