// Splitting a stencil table into slices that each fit a bound on every array, for evaluators
// whose arrays are bounded (Vulkan: one storage buffer binding is at most maxStorageBufferRange,
// one allocation at most maxMemoryAllocationSize; lavapipe binds 128 MiB). A slice is a run of
// consecutive stencils of one batch (so everything it reads was written before it). Its source
// rows are gathered into a compact array [gathered rows | the slice's own rows] and its indices
// renumbered into it, so each array the shader binds is bounded by the slice alone: offsets
// (count + 1), indices and weights (its entries), values ((gathered + count) × width). The
// sums are the same products in the same order, so a sliced run equals the whole table's bit
// for bit.
#pragma once
#include <cstdint>
#include <vector>

#include "loop/stencils.h"

namespace tessera {

struct StencilSlice {
  uint32_t firstStencil = 0;  // of the table: the slice writes rows sourceRows + firstStencil ..
  uint32_t stencilCount = 0;
  uint32_t entryCount = 0;    // its indices and weights
  uint32_t gatheredRows = 0;  // distinct source rows its stencils read
};

// Slices of every batch in order, each as long as `maxArrayBytes` lets its four arrays be (rows
// of `width` floats). Throws LimitError when a single stencil does not fit, naming the stencil,
// the array and the bound.
std::vector<StencilSlice> planStencilSlices(const FloatStencilTable& table, uint32_t width,
                                            uint64_t maxArrayBytes);

// The slice's four arrays, written to the given pointers (room for the sizes above): offsets
// from 0, indices into the gathered rows, weights, and the gathered rows of `rows` (the whole
// table's rows, rowCount() × width) at the start of `values`. `localRow` is scratch of
// rowCount() entries, all kLoopNone before and after the call.
void gatherStencilSlice(const FloatStencilTable& table, const StencilSlice& slice,
                        const float* rows, uint32_t width, std::vector<uint32_t>& localRow,
                        uint32_t* offsets, uint32_t* indices, float* weights, float* values);

}  // namespace tessera
