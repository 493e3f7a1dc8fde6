// Quad-tree leaves → a watertight triangle mesh (docs/watertight.md).
// - Inside a patch: every leaf corner is a vertex, and a leaf whose edges carry corners of
//   finer neighbours is fanned from its split point (an interior point, so the fan is valid),
//   a leaf with only its 4 corners becomes 2 triangles. A rule-T leaf's ring of n vertices
//   becomes n − 2 triangles without a new vertex (ring_triangulation.h): its bound holds for
//   any triangulation of the leaf. Both sides of every edge between
//   leaves use the same vertices: no cracks, no T-junctions.
// - Across patches: a boundary shared by two patches (same control points, either direction;
//   shared_edges.h) carries the union of both sides' vertices, identified by the canonical
//   parameter along the shared curve, so both sides reference the very same vertices.
// - Patch corners and collapsed boundaries are welded by their exact control-point position;
//   triangles that collapse onto an edge are dropped.
// - An unshared side that folds back along its line (side_fold.h) is zipped to itself: a
//   point on one strand is a vertex on every strand that retraces it.
// Vertices are (patch, u, v) only: positions come from an evaluator (GPU or CPU) afterwards.
#pragma once
#include <cstdint>
#include <vector>

#include "geometry/patch.h"
#include "quadtree/quadtree.h"

namespace tessera {

struct ParamVertex {
  uint32_t patchIndex;  // the patch it is evaluated on (one of them, for a welded vertex)
  float u, v;
};

// What identifies a vertex across separate triangulations of the same patches: a point of a
// shared side by (side group, canonical parameter bits); a patch corner, collapsed side or
// fold end by its exact control point; anything else belongs to one patch.
struct SeamKey {
  enum Kind : uint32_t { kOwnPatch, kSharedSide, kPosition };
  uint32_t kind = kOwnPatch;
  uint32_t group = 0;     // kSharedSide: the side group
  uint32_t parameter = 0; // kSharedSide: bits of the canonical parameter
  glm::dvec3 point{0.0};  // kPosition: the control point (in the frame of the patches given)
};

struct ParamMesh {
  std::vector<ParamVertex> vertices;
  std::vector<uint32_t> indices;  // counter-clockwise in (u, v): normals along Pu × Pv
  // Per triangle, its patch and its corners' (u, v) on that patch: a welded vertex keeps one
  // patch's (u, v), so measuring a triangle against its own patch needs these.
  std::vector<uint32_t> trianglePatch;
  std::vector<glm::vec2> cornerUv;  // 3 per triangle
  size_t droppedTriangles = 0;    // collapsed by welding (two corners at one vertex)
  // Rule-T leaves whose bound holds for one diagonal (QuadLeaf::diagonal) that kept the fan
  // around a centre vertex (a fold or a recurring vertex in the ring): their bound is only the
  // any-triangle one then. None on the tea set and the random patches of the tests.
  size_t diagonalFans = 0;
  size_t sharedEdgeGroups = 0;    // patch boundaries found shared
  // Per vertex, when TriangulationScope::seamKeys asks: how another run over other leaves of
  // the same patches names this vertex (streamed_tessellation.h).
  std::vector<SeamKey> seamKeys;
};

struct PatchTopology;

// A triangulation of part of the leaves, for streaming the mesh in patch groups
// (streamed_tessellation.h): the leaves passed are a group's and its neighbours' (so shared
// sides see both sides' points), in the whole tree's order; only the group's become
// triangles. The others' vertices are made too (unreferenced), in the same order as for the
// whole tree, so each shared vertex keeps the (patch, u, v) the whole mesh gives it.
struct TriangulationScope {
  const PatchTopology* topology = nullptr;  // findSharedEdges(patches), computed once; null:
                                            // computed here
  uint32_t firstPatch = 0, endPatch = UINT32_MAX;  // the patches whose leaves become triangles
  bool seamKeys = false;                           // fill ParamMesh::seamKeys
  unsigned threads = 1;  // leaves walked on this many threads (0: all); the mesh is the same
};

ParamMesh triangulateLeaves(const std::vector<QuadLeaf>& leaves,
                            const std::vector<BezierPatch>& patches,
                            const TriangulationScope& scope = {});

}  // namespace tessera
