// The seam of a join (the paper's §3.1 (2)–(3), figure 7): after the triangles inside or across
// the other surface are removed, each mesh is cleaned to one piece with one boundary loop, and
// the two loops are bridged by a strip of triangles starting from their closest vertex pair.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "loop/shapes.h"

namespace tessera {

// Removes faces with remove[f] != 0, then, until nothing changes, the faces of every connected
// piece but the largest and of the smaller fans at vertices the removal pinched (two boundary
// fans meeting at one vertex). Unused vertices are dropped; keptVertex[old] is the new index or
// kLoopNone. Throws std::invalid_argument (naming `what`) if nothing is left.
LoopShape removeFaces(const LoopShape& mesh, const std::vector<uint8_t>& remove,
                      std::vector<uint32_t>& keptVertex, const std::string& what);

// The boundary loops of a mesh, each following its faces' boundary half-edges.
std::vector<std::vector<uint32_t>> boundaryLoops(const LoopControlTopology& topology);

// Triangles joining loop a (vertices of one mesh) to loop b (of the other, indices already in
// the merged numbering), both as boundaryLoops returns them: the strip uses every boundary edge
// once, in the direction opposite to its face's, so the result is consistently oriented. The
// walk starts at the closest pair and each step takes the shorter new rung.
std::vector<uint32_t> bridgeLoops(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b,
                                  const std::vector<glm::dvec3>& positions);

}  // namespace tessera
