// OpenSubdiv (Debian libosd-dev) as the outside reference for our Loop subdivision: builds a
// Far::TopologyRefiner with scheme LOOP from the same control topology, and matches its vertex
// numbering to ours level by level. Used by tests/test_opensubdiv_loop.cpp and
// bench/bench_loop.cpp only; the library itself does not depend on OpenSubdiv.
//
// Options that make OpenSubdiv follow docs/loop.md:
//   VTX_BOUNDARY_EDGE_AND_CORNER  boundary edges sharp, and a boundary vertex of a single face
//                                 a corner (ours: LoopBoundary::EdgeAndCorner, the default).
//   VTX_BOUNDARY_EDGE_ONLY        such a vertex refined with the crease rule instead (ours:
//                                 LoopBoundary::EdgeOnly); osdBoundaryRule maps ours to theirs.
//   creases and marked corners    sharpness Sdc::Crease::SHARPNESS_INFINITE
//   CREASE_UNIFORM (default)      infinitely sharp creases need no Chaikin rule
#pragma once
#include <opensubdiv/far/topologyRefiner.h>

#include <memory>
#include <vector>

#include "loop/topology.h"

namespace tessera::osd {

using OpenSubdiv::Far::TopologyRefiner;
using BoundaryRule = OpenSubdiv::Sdc::Options::VtxBoundaryInterpolation;

std::unique_ptr<TopologyRefiner> makeLoopRefiner(
    const LoopControlTopology& control,
    BoundaryRule boundary = OpenSubdiv::Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);

inline BoundaryRule osdBoundaryRule(LoopBoundary boundary) {
  return boundary == LoopBoundary::EdgeOnly ? OpenSubdiv::Sdc::Options::VTX_BOUNDARY_EDGE_ONLY
                                            : OpenSubdiv::Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER;
}

// ours[l][i]: our index (host/loop/topology.h numbering at level l) of OpenSubdiv's vertex i at
// level l, for l = 0 .. refiner.GetMaxLevel(); `levels` are our topologies of the same levels.
// Throws std::runtime_error if an OpenSubdiv edge has no counterpart in ours.
std::vector<std::vector<uint32_t>> matchVertices(const TopologyRefiner& refiner,
                                                 const std::vector<LoopTopology>& levels);

// A vertex of PrimvarRefinerReal<double>'s interface over glm::dvec3.
struct Point {
  double x = 0, y = 0, z = 0;
  void Clear() { x = y = z = 0; }
  void AddWithWeight(const Point& p, double w) {
    x += w * p.x;
    y += w * p.y;
    z += w * p.z;
  }
};

}  // namespace tessera::osd
