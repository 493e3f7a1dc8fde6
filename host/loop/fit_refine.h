// Fitting with refinement (the paper's §2.3): "the control points and the topology are chosen
// so that the limit surface lies within the user's tolerance ε"; Suzuki's vertex updates run
// until the energy stops falling, "then the control mesh is subdivided". Each round here fits
// every control vertex (loop/fit.h) and measures how far the limit surface lies from the
// target; while some control triangle's part is farther than ε, the control mesh is subdivided
// once by Loop's rules (which keeps its limit surface, so the next round starts from where this
// one ended, with four times the vertices to move) and fitted again, until the surface is within
// ε or a bound on rounds or triangles is reached.
//
// Subdividing only the far triangles (local refinement with T-node splits, loop/local_refine.h,
// as the join does) was tried and measured worse: it does not keep the limit surface, so a
// round could end farther from the target than the one before (a frequency-2
// icosphere cage on the unit sphere at ε = 1e-3: 0.0012 after round 1, 0.0146 after round 2,
// reached only after 8 rounds at 2,924 triangles; subdividing it all: 2.2e-4 in round 2 at 320).
//
// The distance is sampled, one-sided (limit surface → target): at the limit points of the
// control mesh refined once, i.e. per control triangle its three corners and its three edge
// midpoints' limit points, each exactly on the limit surface.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "loop/fit.h"
#include "loop/shapes.h"

namespace tessera {

struct LoopRefiningFitOptions {
  LoopFitOptions fit;            // each round's fit; its `movable` must be empty (all move)
  double tolerance = 0;          // ε, in the target's units; > 0 and finite
  int maxRounds = 5;             // fitting rounds, the first included; 1 fits once
  size_t maxTriangles = 100000;  // no round starts with a control mesh larger than this
};

struct LoopFitRound {
  size_t triangles = 0;     // control triangles fitted in this round
  LoopFitReport fit;
  double distance = 0;      // largest sampled distance after the fit
  size_t farTriangles = 0;  // control triangles with a sample farther than ε
};

struct LoopRefiningFitReport {
  std::vector<LoopFitRound> rounds;
  double distance = 0;  // of the last round
  bool reached = false;  // distance ≤ tolerance
  // Why it stopped: "tolerance" (reached), "rounds" (maxRounds fitted), "triangles" (the next
  // subdivision, 4 × the triangles, would pass maxTriangles).
  std::string stoppedBy;
};

// Fits `cage` (positions and, when subdivided, topology; creases and corners carry over) to
// `target` in place. Throws std::invalid_argument for a tolerance that is not finite and > 0,
// maxRounds < 1 or a non-empty `fit.movable`; MemoryLimitError when a refined round would not fit the memory
// budget (common/memory_budget.h).
LoopRefiningFitReport fitLoopRefining(LoopShape& cage, const TriangleBvh& target,
                                      const LoopRefiningFitOptions& options);

// The largest sampled distance (as above) of each control triangle's part of the limit surface
// to `target`.
std::vector<double> loopFaceDistances(const LoopTopology& topology,
                                      const std::vector<glm::dvec3>& positions,
                                      const TriangleBvh& target);

}  // namespace tessera
