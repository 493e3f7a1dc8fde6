// Quad-tree leaves → triangles without T-junctions inside a patch. Every leaf corner is a
// vertex; a leaf whose edges carry corners of finer neighbours is fanned from its split point
// (an interior point, so the fan is valid in the rectangle), a leaf with only its 4 corners
// becomes 2 triangles. Both sides of every shared edge then use the same vertices.
// Vertices are (patch, u, v) only: positions come from an evaluator (GPU or CPU) afterwards.
#pragma once
#include <cstdint>
#include <vector>

#include "quadtree.h"

namespace tessera {

struct ParamVertex {
  uint32_t patchIndex;
  float u, v;
};

struct ParamMesh {
  std::vector<ParamVertex> vertices;
  std::vector<uint32_t> indices;  // counter-clockwise in (u, v): normals along Pu × Pv
};

ParamMesh triangulateLeaves(const std::vector<QuadLeaf>& leaves);

}  // namespace tessera
