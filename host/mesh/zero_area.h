// Zero-area triangles left after evaluation, removed without opening the mesh.
// Welding equal positions (tessellate.cpp) already drops a triangle with two corners at one
// point. What can remain is a cap: three distinct fp32 positions on one line, the middle one
// between the other two (a strip of surface thinner than fp32 resolves there; the split rules
// avoid making one, kResolvedWidthUlps). A cap is flipped into its neighbour across its long
// edge: the two become the neighbour split at the cap's middle vertex, which covers the same
// region, keeps every edge used as before, and has positive area when the neighbour's far
// corner is off the line (when that corner is between the long edge's ends, the neighbour is
// a cap too, and both become caps over shorter edges for later flips). A cap on an open edge
// goes, and the boundary then runs through its middle vertex, on the same line.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace tessera {

// Whether a, b, c are one line (or a point) exactly: the cross product of fp32 positions is
// exact in double, so this is the zero area every mesh check computes.
bool zeroArea(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

// Flips every cap of `indices` into its neighbour as above, in place (several passes: a flip
// can free another), keeping per triangle its patch and its corners' (u, v) (a flipped pair
// takes the neighbour's patch; the middle vertex's (u, v) there is interpolated along the
// long edge). Returns per triangle whether it goes: the caps on open edges. A cap whose flip
// would repeat an edge stays, as does one whose neighbour's far corner is on the line beyond
// its long edge and no other flip frees it (none in the tea set, even without
// kResolvedWidthUlps: tests/test_tea_set_watertight.cpp).
// The caps are looked for on `threads` threads (0: all); the answer is the same.
std::vector<bool> removeCaps(const std::vector<glm::vec3>& positions,
                             std::vector<uint32_t>& indices, std::vector<uint32_t>& trianglePatch,
                             std::vector<glm::vec2>& cornerUv, unsigned threads = 1);
// The same, the triangles that go as their indices, ascending (none, in the usual case,
// without a flag per triangle to scan).
std::vector<uint32_t> removeCapTriangles(const std::vector<glm::vec3>& positions,
                                         std::vector<uint32_t>& indices,
                                         std::vector<uint32_t>& trianglePatch,
                                         std::vector<glm::vec2>& cornerUv, unsigned threads = 1);

}  // namespace tessera
