// Rational Bézier test surfaces with exact conics (quarter cylinders, a torus) and the views
// that give them zero weights in clip space: cameras whose eye plane passes through a control
// point, as in the comparison of paper 002 (Kawasaki et al., table 1).
#pragma once
#include <string>
#include <vector>

#include "geometry/patch.h"
#include "division/view_dependent.h"

namespace tessera {

// The arc of angle `angle` (0 < angle < π) of the circle of `radius` about the z axis from
// the +x axis, swept from z = 0 to z = height: degree (2, 1), u along the arc (weights 1,
// cos(angle/2), 1), v along z.
RationalBezierPatch quarterCylinder(double radius, double height, double angle = 1.5707963267948966);

// The torus with major radius R and minor radius r about the z axis as 16 biquadratic patches:
// patch 4·a + b has u along quarter a of the tube circle and v along quarter b of the ring.
std::vector<RationalBezierPatch> rationalTorus(double majorRadius, double minorRadius);

struct SampleView {
  std::string name;            // e.g. "cylinder R1 H1, cp (1,0), eye at the control point"
  RationalBezierPatch patch;   // world coordinates, weights > 0
  Camera camera;
  int vanishedWeights = 0;     // control points on the eye plane (w_clip = 0)
};

// Views of quarter cylinders and torus patches from viewpoints on the plane of one of their
// non-corner control points (the eye plane passes through it, so its clip-space weight is 0;
// every other control point is in front, so the patch is): the eye at the control point
// itself and moved sideways within that plane. `full` adds more surfaces and offsets.
std::vector<SampleView> zeroWeightViews(bool full, int width = 1024, int height = 1024,
                                        double fovY = 1.5707963267948966);

}  // namespace tessera
