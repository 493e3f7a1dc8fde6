// The steps that turn evaluated vertices and triangles into a clean mesh (tessellate.cpp and
// streamed_tessellation.cpp share them): equal positions welded, back-to-back pairs found,
// samples checked finite.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "eval/evaluator.h"
#include "mesh/triangulate.h"

namespace tessera {

// For each vertex, the first vertex with bit-identical position (a larger mesh's lookups on
// `threads` threads, 0: all; the answer is the same; position_weld.cpp).
std::vector<uint32_t> weldIdenticalPositions(const std::vector<glm::vec3>& positions,
                                             unsigned threads = 1);

// Triangles whose reverse is in the mesh too (a, b, c and a, c, b): where a fold's strands are
// zipped (side_fold.h), or evaluate to one point, a fan can cover one spot from both sides.
// The two cancel (they bound nothing), and their edges keep the neighbours they had. Settled
// on `threads` threads (0: all); the answer is the same.
std::vector<bool> backToBackPairs(const std::vector<uint32_t>& indices, unsigned threads = 1);
// The same triangles as their indices, ascending: a mesh without any (the usual case) is
// settled without a flag per triangle to scan bit by bit.
std::vector<uint32_t> backToBackTriangles(const std::vector<uint32_t>& indices,
                                          unsigned threads = 1);

// A sample that is not a number or infinite would poison the welding and the writers; fp32
// overflows where a rational patch's weights differ by more than its range can take (a corner
// weight of 10⁻²⁰ against 1: derivatives of order k grow as 10²⁰ᵏ). Throws
// std::invalid_argument naming the patch and (u, v).
void requireFiniteSamples(const ParamMesh& param, const std::vector<gpu::VertexSample>& samples);
// The same for `count` samples at `samples` (of param.vertices' first `count`).
void requireFiniteSamples(const ParamMesh& param, const gpu::VertexSample* samples, size_t count);

}  // namespace tessera
