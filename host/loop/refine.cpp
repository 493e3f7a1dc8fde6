#include "loop/refine.h"

#include <cmath>
#include <stdexcept>

namespace tessera {

double loopBeta(uint32_t k) {
  if (k == 3) return 3.0 / 16.0;
  const double c = 3.0 / 8.0 + 0.25 * std::cos(2.0 * M_PI / double(k));
  return (5.0 / 8.0 - c * c) / double(k);
}

void loopCentredMask(const LoopTopology& t, uint32_t v, double creaseCentre, double creaseSide,
                     double ringWeight, LoopMask& mask) {
  mask.clear();
  const uint32_t k = t.valence(v);
  const uint32_t* ring = t.ring(v);
  switch (t.vertexRule[v]) {
    case LoopVertexRule::Corner:
      mask.add(v, 1.0);
      return;
    case LoopVertexRule::Crease: {
      mask.add(v, creaseCentre);
      const uint32_t* edges = t.ringEdge(v);
      for (uint32_t j = 0; j < k; ++j)
        if (t.edgeSharp[edges[j]]) mask.add(ring[j], creaseSide);
      return;
    }
    case LoopVertexRule::Smooth:
    case LoopVertexRule::Dart:
      mask.add(v, 1.0 - double(k) * ringWeight);
      for (uint32_t j = 0; j < k; ++j) mask.add(ring[j], ringWeight);
      return;
  }
}

void loopVertexMask(const LoopTopology& t, uint32_t v, LoopMask& mask) {
  loopCentredMask(t, v, 0.75, 0.125, loopBeta(t.valence(v)), mask);
}

void loopEdgeMask(const LoopTopology& t, uint32_t e, LoopMask& mask) {
  mask.clear();
  const auto& ends = t.edgeVertices[e];
  if (t.edgeSharp[e]) {
    mask.add(ends[0], 0.5);
    mask.add(ends[1], 0.5);
    return;
  }
  mask.add(ends[0], 0.375);
  mask.add(ends[1], 0.375);
  mask.add(t.oppositeVertex(e, t.edgeFaces[e][0]), 0.125);
  mask.add(t.oppositeVertex(e, t.edgeFaces[e][1]), 0.125);
}

std::vector<glm::dvec3> refineLoopPositions(const LoopTopology& t,
                                            const std::vector<glm::dvec3>& positions) {
  if (positions.size() != t.vertexCount)
    throw std::invalid_argument("refineLoopPositions: " + std::to_string(positions.size()) +
                                " positions for " + std::to_string(t.vertexCount) + " vertices");
  std::vector<glm::dvec3> fine(t.vertexCount + t.edgeCount());
  LoopMask mask;
  for (uint32_t v = 0; v < t.vertexCount; ++v) {
    loopVertexMask(t, v, mask);
    fine[v] = mask.apply(positions);
  }
  for (uint32_t e = 0; e < t.edgeCount(); ++e) {
    loopEdgeMask(t, e, mask);
    fine[t.vertexCount + e] = mask.apply(positions);
  }
  return fine;
}

LoopLevels refineLoop(const LoopTopology& base, const std::vector<glm::dvec3>& positions,
                      int levels) {
  LoopLevels out;
  out.topology.push_back(base);
  out.positions.push_back(positions);
  for (int level = 0; level < levels; ++level) {
    out.positions.push_back(refineLoopPositions(out.topology.back(), out.positions.back()));
    out.topology.push_back(refineLoopTopology(out.topology.back()));
  }
  return out;
}

}  // namespace tessera
