// Trimmed faces (issue 17): what a B-rep face becomes before meshing, independent of where it
// came from (cad/ fills it from STEP, IGES or BRep through Open CASCADE; tests build it by hand).
// A face is its surface, as rational Bézier pieces over rectangles of the face's own (u, v)
// domain, and its trimming loops, as closed polylines in that domain whose points are B-rep
// edge samples. Each sample is discretised once per edge and carries an index into
// TrimmedModel::sharedPoints, so the two faces that share an edge use the very same 3D
// points: that is what makes the mesh watertight across faces (docs/cad.md).
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "bspline/to_bezier.h"

namespace tessera {

// A closed loop: point k joins point k + 1, and the last joins the first (not repeated).
// The material lies to the left of the loop's direction in (u, v): an outer loop runs
// counter-clockwise, a hole clockwise, whatever the face's orientation (see reversed).
struct TrimLoop {
  std::vector<glm::dvec2> uv;       // in the face's (u, v) domain
  std::vector<uint32_t> pointIds;   // one per uv: index into TrimmedModel::sharedPoints
};

// A surface of revolution whose profile is a line (cylinder, cone) or a circle arc (sphere,
// torus), as the reader knows it from the file: the pieces' u turns about the axis (the
// azimuth, monotone in u) and their v runs along the profile (monotone), as Open CASCADE's
// analytic surfaces do. With it, rule T judges a node by its distance to the surface instead of
// the parametric bound (revolution_bound.h): a rational circle is not parametrised by angle,
// and the parametric measure counts that sliding along the surface as error.
struct RevolutionForm {
  enum class Profile : uint8_t { None, Line, Circle };
  Profile profile = Profile::None;  // None: not known, rule T's parametric bound
  glm::dvec3 origin{0.0};           // a point of the axis (a sphere's or torus's centre)
  glm::dvec3 axis{0.0, 0.0, 1.0};   // unit
  // Circle: the profile circle in the meridian half-plane (ρ = distance from the axis,
  // h = height above origin) has its centre at (circleCentre, 0) and radius circleRadius:
  // a sphere (0, R), a torus (R, r).
  double circleCentre = 0.0, circleRadius = 0.0;
};

struct TrimmedFace {
  // The face's surface: piece k covers [u0, u1] × [v0, v1] of the face's (u, v) domain.
  // Pieces of one face meet along whole sides (a B-spline's knot grid).
  std::vector<BezierPatchPiece> pieces;
  RevolutionForm revolution;  // what the pieces are, when known (cylinder, cone, sphere, torus)
  std::vector<TrimLoop> loops;
  // The face's outward normal is −(S_u × S_v) (Open CASCADE's TopAbs_REVERSED): triangles are
  // emitted clockwise in (u, v) so that they face outward.
  bool reversed = false;
  uint32_t faceIndex = 0;  // the face's index in its source model (messages, glb primitives)
  std::string label;       // e.g. "face 12 (#345 ADVANCED_FACE)": what messages name
};

struct TrimmedModel {
  std::vector<TrimmedFace> faces;
  // 3D positions of every trim-loop point: B-rep vertices and edge samples, each once.
  std::vector<glm::dvec3> sharedPoints;
};

}  // namespace tessera
