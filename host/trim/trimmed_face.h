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

struct TrimmedFace {
  // The face's surface: piece k covers [u0, u1] × [v0, v1] of the face's (u, v) domain.
  // Pieces of one face meet along whole sides (a B-spline's knot grid).
  std::vector<BezierPatchPiece> pieces;
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
