// Stencil tables against the direct CPU reference: levels, limit positions and tangents, chained
// and factorized; weights sum to 1 (0 for tangents); any row width; the fp32 mirror.
#include <catch2/catch.hpp>

#include <cmath>

#include "loop/evaluator.h"
#include "loop/limit.h"
#include "loop/shapes.h"
#include "loop/stencils.h"

using namespace tessera;

namespace {

std::vector<double> rowsFrom(const LoopStencils& stencils, const std::vector<glm::dvec3>& p) {
  std::vector<double> rows(stencils.table.rowCount() * 3, 0.0);
  for (size_t v = 0; v < p.size(); ++v)
    for (int c = 0; c < 3; ++c) rows[3 * v + c] = p[v][c];
  return rows;
}

double worstRelative(const std::vector<double>& rows, uint32_t firstRow,
                     const std::vector<glm::dvec3>& expected) {
  double worst = 0, scale = 1e-300;
  for (const auto& e : expected) scale = std::max(scale, glm::length(e));
  for (size_t v = 0; v < expected.size(); ++v) {
    glm::dvec3 got(rows[3 * (firstRow + v)], rows[3 * (firstRow + v) + 1],
                   rows[3 * (firstRow + v) + 2]);
    worst = std::max(worst, glm::length(got - expected[v]) / scale);
  }
  return worst;
}

}  // namespace

TEST_CASE("Loop stencils reproduce the CPU reference at every level, chained and factorized",
          "[loop]") {
  for (const LoopShape& s : {loopBunny(2, 3), loopGrid(6, 5, 4), loopCreasedSphere(2, 4),
                             loopCreasedCube()}) {
    for (bool factorize : {false, true}) {
      INFO(s.name << (factorize ? ", factorized" : ", chained"));
      LoopTopology base = buildLoopTopology(s.topology);
      LoopStencilOptions options;
      options.levels = 3;
      options.limit = options.tangents = true;
      options.factorize = factorize;
      LoopStencils stencils = buildLoopStencils(base, options);
      REQUIRE(stencils.table.batchEnds.size() == (factorize ? 1u : 4u));
      auto rows = rowsFrom(stencils, s.positions);
      applyStencils(stencils.table, rows, 3);
      LoopLevels reference = refineLoop(base, s.positions, 3);
      for (int l = 0; l <= 3; ++l)
        REQUIRE(worstRelative(rows, stencils.levelRow[l], reference.positions[l]) < 1e-14);
      const LoopTopology& last = reference.topology.back();
      REQUIRE(stencils.topology.back().triangles == last.triangles);
      const auto& fine = reference.positions.back();
      REQUIRE(worstRelative(rows, stencils.limitRow, loopLimitPositions(last, fine)) < 1e-14);
      auto tangents = loopLimitTangents(last, fine);
      REQUIRE(worstRelative(rows, stencils.tangent1Row, tangents.tangent1) < 1e-13);
      REQUIRE(worstRelative(rows, stencils.tangent2Row, tangents.tangent2) < 1e-13);

      // Affine: refinement and limit stencils sum to 1, tangent stencils to 0.
      const StencilTable& table = stencils.table;
      for (size_t st = 0; st < table.stencilCount(); ++st) {
        double sum = 0;
        for (uint32_t j = table.offsets[st]; j < table.offsets[st + 1]; ++j) sum += table.weights[j];
        const bool tangent = table.sourceRows + st >= stencils.tangent1Row;
        REQUIRE(std::fabs(sum - (tangent ? 0.0 : 1.0)) < 1e-12);
        if (factorize)
          for (uint32_t j = table.offsets[st]; j < table.offsets[st + 1]; ++j)
            REQUIRE(table.indices[j] < table.sourceRows);
      }
    }
  }
}

TEST_CASE("Loop stencils apply to rows of any width", "[loop]") {
  LoopShape s = loopTorus(6, 4, 0.1, 2);
  LoopStencilOptions options;
  options.levels = 2;
  LoopStencils stencils = buildLoopStencils(buildLoopTopology(s.topology), options);
  const uint32_t width = 5;
  const size_t n = stencils.table.rowCount();
  std::vector<double> wide(n * width, 0.0), narrow(n, 0.0);
  for (uint32_t v = 0; v < s.topology.vertexCount; ++v)
    for (uint32_t c = 0; c < width; ++c) wide[v * width + c] = std::sin(1.0 + v * 0.7 + c * 1.3);
  applyStencils(stencils.table, wide, width);
  for (uint32_t c = 0; c < width; ++c) {
    for (uint32_t v = 0; v < s.topology.vertexCount; ++v) narrow[v] = wide[v * width + c];
    applyStencils(stencils.table, narrow, 1);
    for (size_t r = 0; r < n; ++r) REQUIRE(narrow[r] == wide[r * width + c]);
  }
}

TEST_CASE("Loop stencils: the fp32 mirror stays within float rounding of the double path",
          "[loop]") {
  LoopShape s = loopBunny(3, 17);
  LoopStencilOptions options;
  options.levels = 3;
  options.limit = true;
  LoopStencils stencils = buildLoopStencils(buildLoopTopology(s.topology), options);
  std::vector<float> mirrorRows(stencils.table.rowCount() * 3, 0.0f), cpuRows;
  for (size_t v = 0; v < s.positions.size(); ++v)
    for (int c = 0; c < 3; ++c) mirrorRows[3 * v + c] = float(s.positions[v][c]);
  cpuRows = mirrorRows;
  makeMirrorStencilEvaluator(toFloatStencils(stencils.table), 3)->apply(mirrorRows);
  makeReferenceStencilEvaluator(stencils.table, 3)->apply(cpuRows);
  double worst = 0, largest = 0;
  for (size_t i = 0; i < cpuRows.size(); ++i) {
    worst = std::max(worst, double(std::fabs(mirrorRows[i] - cpuRows[i])));
    largest = std::max(largest, double(std::fabs(cpuRows[i])));
  }
  WARN("fp32 mirror vs double: largest difference " << worst << " (largest coordinate "
                                                    << largest << ")");
  REQUIRE(worst < 4e-7 * largest);
}
