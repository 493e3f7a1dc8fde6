#include "loop/limit.h"

#include <cmath>
#include <stdexcept>

namespace tessera {
namespace {

// Positions of the first two sharp edges in v's ring (a crease vertex has exactly two).
std::pair<uint32_t, uint32_t> creaseEnds(const LoopTopology& t, uint32_t v) {
  const uint32_t* edges = t.ringEdge(v);
  uint32_t ends[2] = {0, 0}, found = 0;
  for (uint32_t j = 0; j < t.valence(v) && found < 2; ++j)
    if (t.edgeSharp[edges[j]]) ends[found++] = j;
  return {ends[0], ends[1]};
}

std::vector<glm::dvec3> applyMasks(const LoopTopology& t, const std::vector<glm::dvec3>& positions,
                                   void (*maskOf)(const LoopTopology&, uint32_t, LoopMask&)) {
  if (positions.size() != t.vertexCount)
    throw std::invalid_argument("Loop limit: " + std::to_string(positions.size()) +
                                " positions for " + std::to_string(t.vertexCount) + " vertices");
  std::vector<glm::dvec3> out(t.vertexCount);
  LoopMask mask;
  for (uint32_t v = 0; v < t.vertexCount; ++v) {
    maskOf(t, v, mask);
    out[v] = mask.apply(positions);
  }
  return out;
}

}  // namespace

double loopChi(uint32_t k) { return 1.0 / (3.0 / (8.0 * loopBeta(k)) + double(k)); }

void loopLimitMask(const LoopTopology& t, uint32_t v, LoopMask& mask) {
  loopCentredMask(t, v, 2.0 / 3.0, 1.0 / 6.0, loopChi(t.valence(v)), mask);
}

void loopLimitTangentMasks(const LoopTopology& t, uint32_t v, LoopMask& t1, LoopMask& t2) {
  t1.clear();
  t2.clear();
  const uint32_t k = t.valence(v);
  const uint32_t* ring = t.ring(v);
  switch (t.vertexRule[v]) {
    case LoopVertexRule::Corner:
      t1.add(v, -3.0);
      t1.add(ring[0], 3.0);
      t2.add(v, -3.0);
      t2.add(ring[1], 3.0);
      return;
    case LoopVertexRule::Crease: {
      auto [lead, trail] = creaseEnds(t, v);
      t1.add(ring[lead], 1.5);
      t1.add(ring[trail], -1.5);
      // Across the crease, into the span from the leading to the trailing edge.
      const uint32_t interior = trail - lead - 1;
      if (interior == 0) {
        t2.add(v, -6.0);
        t2.add(ring[lead], 3.0);
        t2.add(ring[trail], 3.0);
      } else if (interior == 1) {
        t2.add(v, -3.0);
        t2.add(ring[lead + 1], 3.0);
      } else if (interior == 2) {
        const double root3 = std::sqrt(3.0);
        t2.add(v, -root3);
        t2.add(ring[lead], -0.5 * root3);
        t2.add(ring[trail], -0.5 * root3);
        t2.add(ring[lead + 1], root3);
        t2.add(ring[lead + 2], root3);
      } else {
        const double theta = M_PI / double(interior + 1);
        t2.add(ring[lead], -3.0 * std::sin(theta));
        t2.add(ring[trail], -3.0 * std::sin(theta));
        const double scale = -6.0 * (std::cos(theta) - 1.0);
        for (uint32_t i = 1; i <= interior; ++i)
          t2.add(ring[lead + i], scale * std::sin(double(i) * theta));
      }
      return;
    }
    case LoopVertexRule::Smooth:
    case LoopVertexRule::Dart:
      for (uint32_t j = 0; j < k; ++j) {
        const double angle = 2.0 * M_PI * double(j) / double(k);
        t1.add(ring[j], std::cos(angle));
        t2.add(ring[j], std::sin(angle));
      }
      return;
  }
}

std::vector<glm::dvec3> loopLimitPositions(const LoopTopology& t,
                                           const std::vector<glm::dvec3>& positions) {
  return applyMasks(t, positions, loopLimitMask);
}

LoopLimitTangents loopLimitTangents(const LoopTopology& t,
                                    const std::vector<glm::dvec3>& positions) {
  if (positions.size() != t.vertexCount)
    throw std::invalid_argument("Loop limit tangents: " + std::to_string(positions.size()) +
                                " positions for " + std::to_string(t.vertexCount) + " vertices");
  LoopLimitTangents out;
  out.tangent1.resize(t.vertexCount);
  out.tangent2.resize(t.vertexCount);
  LoopMask m1, m2;
  for (uint32_t v = 0; v < t.vertexCount; ++v) {
    loopLimitTangentMasks(t, v, m1, m2);
    out.tangent1[v] = m1.apply(positions);
    out.tangent2[v] = m2.apply(positions);
  }
  return out;
}

std::vector<glm::dvec3> loopLimitNormals(const LoopTopology& t,
                                         const std::vector<glm::dvec3>& positions) {
  LoopLimitTangents tangents = loopLimitTangents(t, positions);
  std::vector<glm::dvec3> normals(t.vertexCount, glm::dvec3(0.0));
  for (uint32_t v = 0; v < t.vertexCount; ++v) {
    const glm::dvec3 n = glm::cross(tangents.tangent1[v], tangents.tangent2[v]);
    const double length = glm::length(n);
    const double scale = glm::length(tangents.tangent1[v]) * glm::length(tangents.tangent2[v]);
    if (length > 1e-12 * scale && length > 0.0) normals[v] = n / length;
  }
  return normals;
}

}  // namespace tessera
