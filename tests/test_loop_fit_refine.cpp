// Fitting with refinement (host/loop/fit_refine.h, the paper's §2.3): rounds of Suzuki fitting,
// each followed by a Loop subdivision while the sampled limit surface is farther than ε from
// the target. A coarse sphere cage needs two rounds and reaches ε; a smooth surface cannot
// reach a cube's edges, so that fit stops at the bound on rounds (or triangles) with the
// distance it reached; the memory budget refuses a round too large for it.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "common/memory_budget.h"
#include "loop/fit_refine.h"
#include "loop/limit.h"
#include "loop/shapes.h"

using namespace tessera;

namespace {

TriangleBvh bvhOf(const LoopShape& s) { return TriangleBvh(s.positions, s.topology.triangles); }

// The limit surface's distance to the target, sampled much more densely than the fit does:
// the control mesh refined 3 levels and pushed to the limit.
double denseDistance(const LoopShape& cage, const TriangleBvh& target) {
  const LoopLevels levels = refineLoop(buildLoopTopology(cage.topology), cage.positions, 3);
  double worst = 0;
  for (const glm::dvec3& p : loopLimitPositions(levels.topology.back(), levels.positions.back()))
    worst = std::max(worst, std::sqrt(target.closest(p).distance2));
  return worst;
}

}  // namespace

TEST_CASE("Fitting with refinement: a coarse sphere cage needs a second round to reach ε",
          "[loop][fit]") {
  LoopShape cage = loopIcosphere(1);  // 20 triangles
  const TriangleBvh target = bvhOf(loopIcosphere(24));
  LoopRefiningFitOptions options;
  options.tolerance = 3e-3;
  const LoopRefiningFitReport r = fitLoopRefining(cage, target, options);
  for (const LoopFitRound& round : r.rounds)
    WARN(round.triangles << " triangles: " << round.fit.iterations << " steps, E "
                         << round.fit.energy.back() << ", sampled distance " << round.distance
                         << ", " << round.farTriangles << " triangles farther than ε");
  REQUIRE(r.reached);
  REQUIRE(r.stoppedBy == "tolerance");
  REQUIRE(r.rounds.size() == 2);
  REQUIRE(r.rounds[0].distance > options.tolerance);  // one fit alone does not reach ε
  REQUIRE(r.rounds[0].triangles == 20);
  REQUIRE(r.rounds[1].triangles == 80);
  REQUIRE(r.distance <= options.tolerance);
  REQUIRE(cage.topology.triangles.size() == 3 * 80);
  const double dense = denseDistance(cage, target);
  WARN("densely sampled distance " << dense << " (fit's samples " << r.distance << ")");
  REQUIRE(dense <= 1.5 * options.tolerance);
}

TEST_CASE("Fitting with refinement: a cube's edges stop it at the bound, with the distance",
          "[loop][fit]") {
  const TriangleBvh cube = bvhOf(loopCreasedCube());
  LoopRefiningFitOptions options;
  options.tolerance = 1e-3;
  options.maxRounds = 3;
  LoopShape cage = loopIcosphere(2);
  const LoopRefiningFitReport byRounds = fitLoopRefining(cage, cube, options);
  REQUIRE_FALSE(byRounds.reached);
  REQUIRE(byRounds.stoppedBy == "rounds");
  REQUIRE(byRounds.rounds.size() == 3);
  REQUIRE(byRounds.distance > options.tolerance);
  REQUIRE(byRounds.distance == byRounds.rounds.back().distance);
  REQUIRE(byRounds.distance < 0.5 * byRounds.rounds.front().distance);  // refining helped
  REQUIRE(cage.topology.triangles.size() == 3 * 80 * 16);

  options.maxRounds = 10;
  options.maxTriangles = 1000;  // 80 → 320; 1280 would pass it
  LoopShape small = loopIcosphere(2);
  const LoopRefiningFitReport byTriangles = fitLoopRefining(small, cube, options);
  REQUIRE_FALSE(byTriangles.reached);
  REQUIRE(byTriangles.stoppedBy == "triangles");
  REQUIRE(byTriangles.rounds.size() == 2);
  REQUIRE(small.topology.triangles.size() == 3 * 320);
}

TEST_CASE("Fitting with refinement: the memory budget refuses a round too large for it",
          "[loop][fit][memory]") {
  const uint64_t saved = memoryBudget();
  setMemoryBudget(1ull << 20);  // round 2's 320 triangles fit; round 3's 1280 do not
  LoopShape cage = loopIcosphere(2);
  LoopRefiningFitOptions options;
  options.tolerance = 1e-9;
  std::string message;
  try {
    fitLoopRefining(cage, bvhOf(loopCreasedCube()), options);
  } catch (const MemoryLimitError& e) {
    message = e.what();
  }
  setMemoryBudget(saved);
  REQUIRE_THAT(message, Catch::Contains("Loop fitting round 3 (1280 control triangles) needs about"));
}

TEST_CASE("Fitting with refinement: creases and corners carry over; bad options refused",
          "[loop][fit]") {
  LoopShape cage = loopCreasedCube();
  const size_t creases = cage.topology.creases.size();
  const TriangleBvh target = bvhOf(loopIcosphere(8));
  LoopRefiningFitOptions options;
  options.tolerance = 1e-9;
  options.maxRounds = 2;
  fitLoopRefining(cage, target, options);
  REQUIRE(cage.topology.creases.size() == 2 * creases);  // each crease edge split in two
  REQUIRE_NOTHROW(buildLoopTopology(cage.topology));

  for (const double bad : {0.0, -1.0, std::nan("")}) {
    options.tolerance = bad;
    REQUIRE_THROWS_WITH(fitLoopRefining(cage, target, options),
                        Catch::Contains("tolerance must be finite and > 0"));
  }
  options.tolerance = 1e-3;
  options.maxRounds = 0;
  REQUIRE_THROWS_WITH(fitLoopRefining(cage, target, options), Catch::Contains("at least 1 round"));
}
