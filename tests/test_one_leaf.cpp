// triangulateOneLeaf (mesh/detail/one_leaf.h): a one-leaf tree over one patch meshed without
// the general setup must be triangulateLeaves' general mesh bit for bit, and the cases it
// cannot tell (shared, collapsed or folded sides, other diagonals, more leaves) must go to
// the general path. The general path is reached by passing a topology (the shortcut declines).
#include <catch2/catch.hpp>

#include <optional>
#include <random>
#include <string>

#include "io/bpt_reader.h"
#include "mesh/detail/one_leaf.h"
#include "mesh/shared_edges.h"
#include "mesh/triangulate.h"
#include "param_mesh_compare.h"

using namespace tessera;
using triangulate_detail::triangulateOneLeaf;

namespace {

QuadLeaf wholeLeaf(uint32_t diagonal) {
  QuadLeaf leaf{};
  leaf.rect = {0.0f, 0.0f, 1.0f, 1.0f};
  leaf.cause = gpu::kCauseWithinTolerance;
  leaf.split = {0.5f, 0.5f};
  leaf.diagonal = diagonal;
  return leaf;
}

ParamMesh generalMesh(const std::vector<QuadLeaf>& leaves, const std::vector<BezierPatch>& patches) {
  const PatchTopology topology = findSharedEdges(patches);
  TriangulationScope scope;
  scope.topology = &topology;
  return triangulateLeaves(leaves, patches, scope);
}

// Bit for bit, and neither mesh asks for seam keys (the fast path declines scopes that do).
void requireSameMesh(const ParamMesh& a, const ParamMesh& b) {
  test::requireSameParamMesh(a, b);
  REQUIRE(a.seamKeys.empty());
  REQUIRE(b.seamKeys.empty());
}

BezierPatch randomPatch(std::mt19937& rng, int degreeU, int degreeV, bool rational) {
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0), weight(0.5, 2.0);
  BezierPatch patch;
  patch.degreeU = degreeU, patch.degreeV = degreeV;
  for (int i = 0; i <= degreeU; ++i)
    for (int j = 0; j <= degreeV; ++j) {
      patch.cp.push_back({i + 0.3 * coordinate(rng), j + 0.3 * coordinate(rng), coordinate(rng)});
      if (rational) patch.weights.push_back(weight(rng));
    }
  return patch;
}

}  // namespace

TEST_CASE("one-leaf triangulation: the general path's mesh on planes and random patches",
          "[triangulate][one_leaf]") {
  std::mt19937 rng(17);
  size_t taken = 0;
  for (int degreeU = 1; degreeU <= 3; ++degreeU)
    for (int degreeV = 1; degreeV <= 3; ++degreeV)
      for (bool rational : {false, true})
        for (uint32_t diagonal : {gpu::kToleranceAnyDiagonal, gpu::kToleranceMainDiagonal}) {
          const std::vector<BezierPatch> patches = {randomPatch(rng, degreeU, degreeV, rational)};
          const std::vector<QuadLeaf> leaves = {wholeLeaf(diagonal)};
          const std::optional<ParamMesh> fast = triangulateOneLeaf(leaves, patches, {});
          REQUIRE(fast);
          requireSameMesh(*fast, generalMesh(leaves, patches));
          requireSameMesh(triangulateLeaves(leaves, patches), generalMesh(leaves, patches));
          ++taken;
        }
  REQUIRE(taken == 36);
}

TEST_CASE("one-leaf triangulation: declined where the general path decides something",
          "[triangulate][one_leaf]") {
  std::mt19937 rng(5);
  const BezierPatch plain = randomPatch(rng, 3, 3, false);
  const std::vector<QuadLeaf> one = {wholeLeaf(gpu::kToleranceAnyDiagonal)};

  BezierPatch collapsed = plain;  // side v = 0 a pole: a cone's apex
  for (int i = 0; i <= 3; ++i) collapsed.at(i, 0) = collapsed.at(0, 0);
  BezierPatch seam = plain;  // sides u = 0 and u = 1 one curve: a closed surface's seam
  for (int j = 0; j <= 3; ++j) seam.at(3, j) = seam.at(0, j);
  BezierPatch folded = plain;  // side v = 0 on one line, out to +a and back (side_fold.h)
  const double xs[4] = {-1.0, 1.0, 0.0, 0.0};
  for (int i = 0; i <= 3; ++i) folded.at(i, 0) = {xs[i], 0.0, 0.0};
  for (const BezierPatch& patch : {collapsed, seam, folded}) {
    const std::vector<BezierPatch> patches = {patch};
    REQUIRE_FALSE(triangulateOneLeaf(one, patches, {}));
    requireSameMesh(triangulateLeaves(one, patches), generalMesh(one, patches));
  }

  const std::vector<BezierPatch> patches = {plain};
  REQUIRE_FALSE(triangulateOneLeaf({wholeLeaf(gpu::kToleranceAntiDiagonal)}, patches, {}));
  QuadLeaf part = wholeLeaf(gpu::kToleranceAnyDiagonal);
  part.rect.z = 0.5f;
  REQUIRE_FALSE(triangulateOneLeaf({part}, patches, {}));
  REQUIRE_FALSE(triangulateOneLeaf({part, part}, patches, {}));
  REQUIRE_FALSE(triangulateOneLeaf(one, {plain, plain}, {}));
  TriangulationScope seamKeys;
  seamKeys.seamKeys = true;
  REQUIRE_FALSE(triangulateOneLeaf(one, patches, seamKeys));
  // The anti-diagonal leaf still gets its own diagonal from the general path.
  const ParamMesh anti = triangulateLeaves({wholeLeaf(gpu::kToleranceAntiDiagonal)}, patches);
  REQUIRE(anti.indices != triangulateOneLeaf(one, patches, {})->indices);
}

TEST_CASE("one-leaf triangulation: every tea set patch alone, taken or declined, the same mesh",
          "[triangulate][one_leaf]") {
  size_t taken = 0, declined = 0;
  for (const char* model : {"teapot", "teacup", "teaspoon"}) {
    const std::vector<BezierPatch> all =
        readBpt(std::string(TESSERA_SOURCE_DIR "/data/") + model + ".bpt");
    for (const BezierPatch& patch : all) {
      const std::vector<BezierPatch> patches = {patch};
      const std::vector<QuadLeaf> leaves = {wholeLeaf(gpu::kToleranceMainDiagonal)};
      const ParamMesh general = generalMesh(leaves, patches);
      if (triangulateOneLeaf(leaves, patches, {})) ++taken;
      else ++declined;
      requireSameMesh(triangulateLeaves(leaves, patches), general);
    }
  }
  // The lids' poles, the teaspoon's folded handle tip: both kinds occur.
  REQUIRE(taken > 0);
  REQUIRE(declined > 0);
}
