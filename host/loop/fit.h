// Fitting a Loop control mesh to a target surface (Suzuki et al. 1999, the paper's §2.3): each
// control vertex p moves by p ← p − λ(p∞ − q), q the closest point on the target to its limit
// point p∞ (found with a BVH), until E = Σ|p∞ − q|² falls below a threshold or stops
// improving. Joining fits only the vertices it changed (`movable`); the rest stay bit for bit.
#pragma once
#include <glm/glm.hpp>

#include <vector>

#include "loop/bvh.h"
#include "loop/topology.h"

namespace tessera {

struct LoopFitOptions {
  double lambda = 1.0;            // the paper's λ (1 converges best, §2.3)
  double energyThreshold = 0.0;   // stop when E ≤ this (absolute, squared length units)
  double minImprovement = 1e-4;   // stop when E falls by less than this fraction in a step
  int maxIterations = 100;
  // Vertices that may move (empty: all). Their energy is what E sums.
  std::vector<uint8_t> movable;
};

struct LoopFitReport {
  std::vector<double> energy;  // E before each step, and after the last one kept
  int iterations = 0;          // steps kept
  double maxDistance = 0;      // max |p∞ − q| over the movable vertices at the end
};

// Several targets at once (joining: each side's vertices go back to their own surface): vertex
// v is fitted to targets[targetOf[v] − 1], and stays where it is when targetOf[v] is 0.
// options.movable is ignored.
LoopFitReport fitLoopToSurfaces(const LoopTopology& topology, std::vector<glm::dvec3>& positions,
                                const std::vector<const TriangleBvh*>& targets,
                                const std::vector<uint8_t>& targetOf,
                                const LoopFitOptions& options = {});

// The energy and max distance of the current control positions against `target`.
double loopFitEnergy(const LoopTopology& topology, const std::vector<glm::dvec3>& positions,
                     const TriangleBvh& target, const std::vector<uint8_t>& movable,
                     double* maxDistance = nullptr);

// Moves `positions` in place. A step that would raise E is undone and ends the fit.
LoopFitReport fitLoopToSurface(const LoopTopology& topology, std::vector<glm::dvec3>& positions,
                               const TriangleBvh& target, const LoopFitOptions& options = {});

// A dense triangle mesh of the limit surface of (topology, positions): refined `levels` times
// and pushed to the limit. The usual fitting target for "the original surface".
TriangleBvh loopLimitSurfaceBvh(const LoopTopology& topology,
                                const std::vector<glm::dvec3>& positions, int levels);

}  // namespace tessera
