#include "loop/fit_refine.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/memory_budget.h"
#include "loop/limit.h"
#include "loop/stencils.h"

namespace tessera {

std::vector<double> loopFaceDistances(const LoopTopology& t,
                                      const std::vector<glm::dvec3>& positions,
                                      const TriangleBvh& target) {
  // One level finer: vertex v stays v, the vertex on edge e is vertexCount + e (refine.h).
  const std::vector<glm::dvec3> refined = refineLoopPositions(t, positions);
  const std::vector<glm::dvec3> limit = loopLimitPositions(refineLoopTopology(t), refined);
  std::vector<double> sampleDistance(limit.size());
  for (size_t i = 0; i < limit.size(); ++i)
    sampleDistance[i] = std::sqrt(target.closest(limit[i]).distance2);
  std::vector<double> faces(t.faceCount(), 0.0);
  for (size_t f = 0; f < t.faceCount(); ++f)
    for (int i = 0; i < 3; ++i)
      faces[f] = std::max({faces[f], sampleDistance[t.triangles[3 * f + i]],
                           sampleDistance[t.vertexCount + t.faceEdges[3 * f + i]]});
  return faces;
}

namespace {

// `cage` refined once by Loop's rules: even vertex v keeps index v (so the marked corners
// stay), the new vertex of edge e is vertexCount + e, and crease edges are inherited.
void subdivide(LoopShape& cage, const LoopTopology& topology) {
  const LoopTopology fine = refineLoopTopology(topology);
  cage.positions = refineLoopPositions(topology, cage.positions);
  cage.topology.vertexCount = fine.vertexCount;
  cage.topology.triangles = fine.triangles;
  cage.topology.creases.clear();
  for (size_t e = 0; e < fine.edgeCount(); ++e)
    if (fine.edgeCrease[e]) cage.topology.creases.push_back(fine.edgeVertices[e]);
}

}  // namespace

LoopRefiningFitReport fitLoopRefining(LoopShape& cage, const TriangleBvh& target,
                                      const LoopRefiningFitOptions& options) {
  if (!(std::isfinite(options.tolerance) && options.tolerance > 0))
    throw std::invalid_argument("Loop fitting: the tolerance must be finite and > 0, got " +
                                std::to_string(options.tolerance));
  if (options.maxRounds < 1)
    throw std::invalid_argument("Loop fitting: at least 1 round, got " +
                                std::to_string(options.maxRounds));
  if (!options.fit.movable.empty())
    throw std::invalid_argument("Loop fitting with refinement moves every vertex: `movable` "
                                "must be empty");
  LoopRefiningFitReport report;
  for (int round = 1;; ++round) {
    const LoopTopology topology = buildLoopTopology(cage.topology);
    LoopFitRound r;
    r.triangles = topology.faceCount();
    r.fit = fitLoopToSurface(topology, cage.positions, target, options.fit);
    const std::vector<double> distances = loopFaceDistances(topology, cage.positions, target);
    for (const double d : distances) {
      r.distance = std::max(r.distance, d);
      r.farTriangles += d > options.tolerance;
    }
    report.rounds.push_back(r);
    report.distance = r.distance;
    if (r.farTriangles == 0) {
      report.reached = true;
      report.stoppedBy = "tolerance";
      return report;
    }
    if (round == options.maxRounds) {
      report.stoppedBy = "rounds";
      return report;
    }
    // One level of Loop subdivision: the same limit surface on four times the triangles, so
    // the next round starts from the surface this one ended with, with more freedom.
    const size_t next = 4 * r.triangles;
    if (next > options.maxTriangles) {
      report.stoppedBy = "triangles";
      return report;
    }
    // The next round's work (its topology, one level finer for the samples, their limit
    // points) is that of a one-level stencil table with limits on its triangles.
    LoopStencilOptions sampled;
    sampled.levels = 1;
    sampled.limit = true;
    requireWithinMemoryBudget(estimatedLoopStencilBytes(next, sampled),
                              "Loop fitting round " + std::to_string(round + 1) + " (" +
                                  std::to_string(next) + " control triangles)");
    subdivide(cage, topology);
  }
}

}  // namespace tessera
