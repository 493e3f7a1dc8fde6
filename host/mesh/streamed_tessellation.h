// tessellate() for a mesh larger than the memory budget (issue 18): the patches go in groups
// of consecutive indices; each group's quad-tree, triangles and vertices are made, handed to a
// sink (the output file's writer, io/mesh_stream_writer.h) and dropped before the next group.
// What persists across groups is the welding map of the vertices on patch boundaries (shared
// sides, corners, collapsed sides) that a patch of a later group can meet, so a later group's
// triangles reference the very vertices an earlier group wrote, and the mesh stays watertight
// across groups.
//
// A group's triangulation needs the points its neighbours put on their shared sides (both
// sides' leaf corners are vertices of both): the tree is built for the group and the patches
// that share a side with it, and only the group's own leaves are triangulated.
//
// The result has the held mesh's triangles (tests/test_streamed_tessellation.cpp: the same
// set of position triples, closed, no T-junction) but not its numbering: the held mesh numbers
// vertices in the order of the whole tree's leaves and keeps welded duplicates unreferenced;
// the streamed one numbers them group by group and writes each once.
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/tessellate.h"

namespace tessera {

// One group's share of the mesh, in model coordinates.
struct MeshChunk {
  // The vertices first met in this group; their indices continue the previous chunks'.
  std::vector<glm::vec3> positions, normals;
  std::vector<glm::vec2> uvs;
  std::vector<uint32_t> patchIds;
  std::vector<uint32_t> indices;  // may reference earlier chunks' vertices
  std::vector<uint32_t> trianglePatch;
};
using MeshChunkSink = std::function<void(const MeshChunk&)>;

struct StreamedTessellationStats {
  TessellationStats totals;     // summed over the groups (levels left empty)
  size_t groups = 0;
  size_t patchesPerGroup = 0;   // the group size used (after halving, in the automatic mode)
  size_t seamVertices = 0;      // the most entries the welding map held (a vertex is kept
                                // until the group of the last patch that can meet it)
  uint64_t largestGroupBytes = 0;  // the largest group's estimate, welding map included
  double largestLeafBound = 0;  // rule T: the largest leaf bound, in model units
};

// Bytes per entry of the welding map that persists across groups (key, index, position and
// the hash table's node), for the memory budget.
constexpr size_t kSeamVertexBytes = 64;

// `patchesPerGroup` > 0: groups of that many patches; a group whose estimate exceeds the
// memory budget throws MemoryLimitError (exit 4). 0: start at an eighth of the patches and
// halve a group that does not fit, down to one patch (which then throws as above).
// Otherwise as tessellate(); the triangles reach `sink` group by group.
StreamedTessellationStats tessellateStreamed(const std::vector<BezierPatch>& patches,
                                             const QuadtreeOptions& options, Backend& backend,
                                             size_t patchesPerGroup, const MeshChunkSink& sink);

}  // namespace tessera
