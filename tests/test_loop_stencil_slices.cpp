// Stencil tables in slices (host/loop/stencil_slices.h), as the Vulkan evaluator applies a table
// larger than the device's array bound: every slice keeps each array within the bound, the
// slices cover every stencil of every batch once and in order, and applying them one by one
// through the fp32 mirror gives the whole table's result bit for bit. The same on Vulkan is in
// test_loop_gpu.cpp.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

#include "loop/detail/stencil_mirror.h"
#include "loop/evaluator.h"
#include "loop/shapes.h"
#include "loop/stencil_slices.h"
#include "tessera/errors.h"

using namespace tessera;

namespace {

std::vector<float> controlRows(const LoopShape& shape, const FloatStencilTable& table,
                               uint32_t width) {
  std::vector<float> rows(table.rowCount() * width, 0.0f);
  for (size_t v = 0; v < shape.positions.size(); ++v)
    for (uint32_t c = 0; c < width; ++c)
      rows[v * width + c] = c < 3 ? float(shape.positions[v][c]) : float(std::cos(0.7 * v + c));
  return rows;
}

// What the sliced Vulkan path does, with the mirror in place of the dispatch.
void applySliced(const FloatStencilTable& table, const std::vector<StencilSlice>& slices,
                 uint32_t width, std::vector<float>& rows) {
  std::vector<uint32_t> localRow(table.rowCount(), kLoopNone);
  for (const StencilSlice& s : slices) {
    std::vector<uint32_t> offsets(s.stencilCount + 1), indices(s.entryCount);
    std::vector<float> weights(s.entryCount), values((s.gatheredRows + s.stencilCount) * width);
    gatherStencilSlice(table, s, rows.data(), width, localRow, offsets.data(), indices.data(),
                       weights.data(), values.data());
    mirror::applyStencils(offsets.data(), indices.data(), weights.data(), values.data(), 0,
                          s.stencilCount, s.gatheredRows, width);
    std::memcpy(rows.data() + (size_t(table.sourceRows) + s.firstStencil) * width,
                values.data() + size_t(s.gatheredRows) * width,
                size_t(s.stencilCount) * width * sizeof(float));
  }
  for (uint32_t r : localRow) REQUIRE(r == kLoopNone);  // the scratch is left clean
}

}  // namespace

TEST_CASE("Loop stencils in slices: bounded arrays, every stencil once, bit for bit the whole",
          "[loop]") {
  for (const LoopShape& shape : {loopBunny(2, 3), loopGrid(6, 5, 4), loopCreasedSphere(2, 4)}) {
    for (const bool factorize : {false, true}) {
      LoopStencilOptions options;
      options.levels = 3;
      options.limit = options.tangents = true;
      options.factorize = factorize;
      const FloatStencilTable table =
          toFloatStencils(buildLoopStencils(buildLoopTopology(shape.topology), options).table);
      const uint32_t width = 4;
      // Small enough for many slices per batch, large enough for the widest stencil (a
      // factorized level-3 stencil reads tens of control rows).
      const uint64_t bound = factorize ? 4096 : 512;
      INFO(shape.name << (factorize ? " factorized" : " chained") << ", bound " << bound);
      const std::vector<StencilSlice> slices = planStencilSlices(table, width, bound);
      REQUIRE(slices.size() > 4 * table.batchEnds.size());

      // Consecutive, within one batch each, and within the bound in every array.
      uint32_t next = 0;
      for (const StencilSlice& s : slices) {
        REQUIRE(s.firstStencil == next);
        REQUIRE(s.stencilCount > 0);
        next += s.stencilCount;
        const auto batch = std::upper_bound(table.batchEnds.begin(), table.batchEnds.end(),
                                            s.firstStencil);
        REQUIRE(batch != table.batchEnds.end());
        REQUIRE(s.firstStencil + s.stencilCount <= *batch);
        REQUIRE(s.entryCount == table.offsets[next] - table.offsets[s.firstStencil]);
        REQUIRE((s.stencilCount + 1) * sizeof(uint32_t) <= bound);
        REQUIRE(s.entryCount * sizeof(float) <= bound);
        REQUIRE((s.gatheredRows + s.stencilCount) * width * sizeof(float) <= bound);
        REQUIRE(s.gatheredRows <= s.entryCount);
      }
      REQUIRE(next == table.stencilCount());

      std::vector<float> whole = controlRows(shape, table, width), sliced = whole;
      makeMirrorStencilEvaluator(table, width)->apply(whole);
      applySliced(table, slices, width, sliced);
      REQUIRE(std::memcmp(whole.data(), sliced.data(), whole.size() * sizeof(float)) == 0);
    }
  }
}

TEST_CASE("Loop stencils in slices: a stencil larger than the bound is a LimitError naming it",
          "[loop]") {
  LoopStencilOptions options;
  options.levels = 2;
  const FloatStencilTable table =
      toFloatStencils(buildLoopStencils(buildLoopTopology(loopIcosphere(1).topology), options).table);
  // Stencil 0 is a vertex of valence 5: six source rows of 3 floats and its own row, 84 bytes.
  REQUIRE_THROWS_MATCHES(planStencilSlices(table, 3, 64), LimitError,
                         Catch::Message("Loop stencils: stencil 0 alone needs more vertex data "
                                        "than the 64 bytes one device array may hold"));
  REQUIRE_NOTHROW(planStencilSlices(table, 3, 96));
}
