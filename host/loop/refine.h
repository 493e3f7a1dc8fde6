// Loop subdivision's refinement rules (Loop 1987; boundaries and creases as in Hoppe et al.
// 1994 and OpenSubdiv's Sdc) as masks: the weights of level-l vertices that make one level-l+1
// vertex. The CPU reference (refineLoopPositions) applies them in double; the stencil builder
// (loop_stencils.h) stores them for the evaluators.
//
//   edge vertex, smooth edge:  3/8 of each end, 1/8 of each opposite vertex
//   edge vertex, sharp edge:   1/2 of each end (boundary or crease edge)
//   vertex, smooth or dart:    (1 − kβ) p + β Σ p_j over its k neighbours,
//                              β = 3/16 for k = 3, else (1/k)(5/8 − (3/8 + ¼cos(2π/k))²)
//   vertex, crease:            3/4 p + 1/8 of each of its two sharp-edge neighbours
//   vertex, corner:            p
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

#include "loop/topology.h"

namespace tessera {

// Weights of source vertices for one destination value, in the order they are summed.
struct LoopMask {
  std::vector<uint32_t> indices;
  std::vector<double> weights;
  void clear() {
    indices.clear();
    weights.clear();
  }
  void add(uint32_t index, double weight) {
    indices.push_back(index);
    weights.push_back(weight);
  }
  size_t size() const { return indices.size(); }
  // Σ weights[j] · values[indices[j]], summed in order.
  glm::dvec3 apply(const std::vector<glm::dvec3>& values) const {
    glm::dvec3 sum(0.0);
    for (size_t j = 0; j < indices.size(); ++j) sum += weights[j] * values[indices[j]];
    return sum;
  }
};

// Loop's β for a smooth vertex of valence k ≥ 3. The general formula gives 3/16 at k = 3 too,
// and 1/16 at the regular valence 6.
double loopBeta(uint32_t k);

// The shape shared by Loop's vertex-centred masks (refinement and limit): a corner keeps p; a
// crease vertex takes creaseCentre·p + creaseSide·(each of its two sharp-edge neighbours); a
// smooth vertex or dart of valence k takes (1 − k·ringWeight) p + ringWeight Σ p_j. The vertex
// comes first, then its neighbours in ring order.
void loopCentredMask(const LoopTopology& topology, uint32_t v, double creaseCentre,
                     double creaseSide, double ringWeight, LoopMask& mask);
// The level-l+1 vertex that vertex v becomes: v itself first, then its ring in ring order.
void loopVertexMask(const LoopTopology& topology, uint32_t v, LoopMask& mask);
// The new vertex on edge e: its two ends (lower index first), then the opposite vertices.
void loopEdgeMask(const LoopTopology& topology, uint32_t e, LoopMask& mask);

// One level of refinement of per-vertex positions, in double (the accuracy reference). The
// result is indexed like refineLoopTopology(topology): vertices, then one per edge.
std::vector<glm::dvec3> refineLoopPositions(const LoopTopology& topology,
                                            const std::vector<glm::dvec3>& positions);

// A control mesh refined `levels` times: every level's topology and positions (level 0 first).
struct LoopLevels {
  std::vector<LoopTopology> topology;
  std::vector<std::vector<glm::dvec3>> positions;
};
LoopLevels refineLoop(const LoopTopology& base, const std::vector<glm::dvec3>& positions,
                      int levels);

}  // namespace tessera
