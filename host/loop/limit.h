// Limit points and limit normals of Loop surfaces: where each control vertex goes after
// infinitely many refinements, without refining (Hoppe et al. 1994; the paper's §2.2).
//
//   smooth or dart vertex:  p∞ = (1 − kχ) p + χ Σ p_j,  χ = 1 / (3/(8β) + k)
//   crease/boundary vertex: p∞ = 2/3 p + 1/6 of each of its two sharp-edge neighbours
//   corner:                 p∞ = p
//
// Tangent masks are OpenSubdiv's (Sdc::Scheme<SCHEME_LOOP>), scale factors included, so that
// tangents, not only normals, can be compared with it: interior Σ cos(2πj/k) p_j and
// Σ sin(2πj/k) p_j; along a crease 3/2 (p_lead − p_trail) and across it the half-disc formula;
// at a corner 3 (p_0 − p) and 3 (p_1 − p). The normal is tangent1 × tangent2, which points to
// the side the triangles' counter-clockwise winding faces. At an interior crease vertex the
// tangents are those of the span that follows the first crease edge in ring order.
#pragma once
#include <glm/glm.hpp>

#include <vector>

#include "loop/refine.h"

namespace tessera {

// The paper's χ for valence k.
double loopChi(uint32_t k);

void loopLimitMask(const LoopTopology& topology, uint32_t v, LoopMask& mask);
void loopLimitTangentMasks(const LoopTopology& topology, uint32_t v, LoopMask& tangent1,
                           LoopMask& tangent2);

std::vector<glm::dvec3> loopLimitPositions(const LoopTopology& topology,
                                           const std::vector<glm::dvec3>& positions);
struct LoopLimitTangents {
  std::vector<glm::dvec3> tangent1, tangent2;
};
LoopLimitTangents loopLimitTangents(const LoopTopology& topology,
                                    const std::vector<glm::dvec3>& positions);
// Unit normals tangent1 × tangent2; (0, 0, 0) where the tangents are parallel or zero.
std::vector<glm::dvec3> loopLimitNormals(const LoopTopology& topology,
                                         const std::vector<glm::dvec3>& positions);

}  // namespace tessera
