#include "loop/fit.h"

#include <cmath>
#include <stdexcept>

#include "loop/limit.h"

namespace tessera {
namespace {

// Which target vertex v goes to: targetOf[v] − 1, none (0) for a fixed vertex; an empty
// targetOf moves every vertex towards target 0.
uint32_t targetIndex(const std::vector<uint8_t>& targetOf, uint32_t v) {
  return targetOf.empty() ? 1u : targetOf[v];
}
bool isMovable(const std::vector<uint8_t>& targetOf, uint32_t v) {
  return targetIndex(targetOf, v) != 0;
}

// E and, per movable vertex, Δ = p∞ − q (the paper's equation 2).
double energyAndSteps(const LoopTopology& t, const std::vector<glm::dvec3>& positions,
                      const std::vector<const TriangleBvh*>& targets,
                      const std::vector<uint8_t>& movable, std::vector<glm::dvec3>* steps,
                      double* maxDistance) {
  const std::vector<glm::dvec3> limit = loopLimitPositions(t, positions);
  double energy = 0, worst = 0;
  if (steps) steps->assign(t.vertexCount, glm::dvec3(0.0));
  for (uint32_t v = 0; v < t.vertexCount; ++v) {
    if (!isMovable(movable, v)) continue;
    const MeshClosestPoint q = targets[targetIndex(movable, v) - 1]->closest(limit[v]);
    energy += q.distance2;
    worst = std::max(worst, std::sqrt(q.distance2));
    if (steps) (*steps)[v] = limit[v] - q.point;
  }
  if (maxDistance) *maxDistance = worst;
  return energy;
}

}  // namespace

double loopFitEnergy(const LoopTopology& t, const std::vector<glm::dvec3>& positions,
                     const TriangleBvh& target, const std::vector<uint8_t>& movable,
                     double* maxDistance) {
  return energyAndSteps(t, positions, {&target}, movable, nullptr, maxDistance);
}

LoopFitReport fitLoopToSurface(const LoopTopology& t, std::vector<glm::dvec3>& positions,
                               const TriangleBvh& target, const LoopFitOptions& options) {
  return fitLoopToSurfaces(t, positions, {&target}, options.movable, options);
}

LoopFitReport fitLoopToSurfaces(const LoopTopology& t, std::vector<glm::dvec3>& positions,
                                const std::vector<const TriangleBvh*>& targets,
                                const std::vector<uint8_t>& targetOf,
                                const LoopFitOptions& options) {
  if (!targetOf.empty() && targetOf.size() != t.vertexCount)
    throw std::invalid_argument("Loop fitting: " + std::to_string(targetOf.size()) +
                                " vertex flags for " + std::to_string(t.vertexCount) + " vertices");
  for (uint8_t k : targetOf)
    if (k > targets.size())
      throw std::invalid_argument("Loop fitting: target " + std::to_string(k) + " of " +
                                  std::to_string(targets.size()));
  if (!(options.lambda > 0.0 && options.lambda <= 2.0))
    throw std::invalid_argument("Loop fitting: λ = " + std::to_string(options.lambda) +
                                " is outside (0, 2]");
  const std::vector<uint8_t>& movable = targetOf;
  LoopFitReport report;
  std::vector<glm::dvec3> steps, previous;
  double energy = energyAndSteps(t, positions, targets, movable, &steps,
                                 &report.maxDistance);
  report.energy.push_back(energy);
  for (int i = 0; i < options.maxIterations && energy > options.energyThreshold; ++i) {
    previous = positions;
    for (uint32_t v = 0; v < t.vertexCount; ++v)
      if (isMovable(movable, v)) positions[v] -= options.lambda * steps[v];
    double distance = 0;
    std::vector<glm::dvec3> nextSteps;
    const double next = energyAndSteps(t, positions, targets, movable, &nextSteps, &distance);
    if (next >= energy) {  // no longer improving: keep the better positions
      positions.swap(previous);
      break;
    }
    report.energy.push_back(next);
    ++report.iterations;
    report.maxDistance = distance;
    steps.swap(nextSteps);
    const bool stalled = next > energy * (1.0 - options.minImprovement);
    energy = next;
    if (stalled) break;
  }
  return report;
}

TriangleBvh loopLimitSurfaceBvh(const LoopTopology& topology,
                                const std::vector<glm::dvec3>& positions, int levels) {
  LoopLevels refined = refineLoop(topology, positions, levels);
  return TriangleBvh(loopLimitPositions(refined.topology.back(), refined.positions.back()),
                     refined.topology.back().triangles);
}

}  // namespace tessera
