// Stencil tables, OpenSubdiv Far-style: the CPU turns Loop topology into weights, and an
// evaluator (CPU double, fp32 mirror, Vulkan; loop_evaluator.h) applies them to any per-vertex
// data. One table covers every level: rows are [control vertices | level 1 | … | level L |
// limit positions | tangent 1 | tangent 2], stencil s writes row sourceRows + s, and batches are
// applied in order (a barrier between them on the GPU) because each level reads the one before.
#pragma once
#include <cstdint>
#include <vector>

#include "loop/refine.h"
#include "loop/topology.h"

namespace tessera {

struct StencilTable {
  uint32_t sourceRows = 0;             // rows given by the caller (the control vertices)
  std::vector<uint32_t> offsets{0};    // stencil s: entries offsets[s] .. offsets[s + 1]
  std::vector<uint32_t> indices;       // source rows, summed in this order
  std::vector<double> weights;
  std::vector<uint32_t> batchEnds;     // stencils of batch b: [batchEnds[b − 1], batchEnds[b])

  size_t stencilCount() const { return offsets.size() - 1; }
  size_t rowCount() const { return sourceRows + stencilCount(); }
  void append(const LoopMask& mask, uint32_t rowOffset);
  void endBatch() { batchEnds.push_back(uint32_t(stencilCount())); }
};

// The same table with fp32 weights: what the mirror and the shader read.
struct FloatStencilTable {
  uint32_t sourceRows = 0;
  std::vector<uint32_t> offsets;
  std::vector<uint32_t> indices;
  std::vector<float> weights;
  std::vector<uint32_t> batchEnds;

  size_t stencilCount() const { return offsets.size() - 1; }
  size_t rowCount() const { return sourceRows + stencilCount(); }
};
FloatStencilTable toFloatStencils(const StencilTable& table);

struct LoopStencilOptions {
  int levels = 1;          // uniform refinement levels, ≥ 0
  bool limit = false;      // add the limit positions of the last level's vertices
  bool tangents = false;   // add the two limit tangents of the last level's vertices
  // false: each level's stencils read the level before (small, one batch per level);
  // true: every stencil reads the control vertices only (one batch, larger stencils).
  bool factorize = false;
};

struct LoopStencils {
  StencilTable table;
  std::vector<LoopTopology> topology;   // level 0 (the base) .. L
  std::vector<uint32_t> levelRow;       // first row of each level's vertices
  uint32_t limitRow = kLoopNone;        // first row of the limit positions, if asked for
  uint32_t tangent1Row = kLoopNone, tangent2Row = kLoopNone;
};

// Throws MemoryLimitError (common/memory_budget.h) when estimatedLoopStencilBytes exceeds the
// memory budget, before any level is built.
LoopStencils buildLoopStencils(const LoopTopology& base, const LoopStencilOptions& options);

// The bytes buildLoopStencils and an evaluator's run hold for `baseFaces` control triangles
// under `options` (every level's topology, the chained stencil tables in double and fp32, the
// rows and the output mesh): faces × 4^levels times bytes per face from the structs' sizes
// (derivation in stencils.cpp).
uint64_t estimatedLoopStencilBytes(size_t baseFaces, const LoopStencilOptions& options);

// Applies `table` in double. `rows` holds rowCount() × width values; the first sourceRows ×
// width are read, the rest written.
void applyStencils(const StencilTable& table, std::vector<double>& rows, uint32_t width);

}  // namespace tessera
