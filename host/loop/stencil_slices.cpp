#include "loop/stencil_slices.h"

#include <cstring>
#include <string>

#include "tessera/errors.h"

namespace tessera {
namespace {

// Whether a slice of `count` stencils, `entries` entries and `gathered` source rows keeps each
// of its four arrays within `limit` bytes.
bool fits(uint64_t count, uint64_t entries, uint64_t gathered, uint32_t width, uint64_t limit,
          const char** array) {
  const struct { const char* what; uint64_t bytes; } arrays[] = {
      {"stencil offsets", (count + 1) * sizeof(uint32_t)},
      {"stencil indices", entries * sizeof(uint32_t)},
      {"stencil weights", entries * sizeof(float)},
      {"vertex data", (gathered + count) * width * sizeof(float)}};
  for (const auto& a : arrays)
    if (a.bytes > limit) {
      *array = a.what;
      return false;
    }
  return true;
}

}  // namespace

std::vector<StencilSlice> planStencilSlices(const FloatStencilTable& table, uint32_t width,
                                            uint64_t maxArrayBytes) {
  std::vector<StencilSlice> slices;
  // seenBy[row]: the last slice that gathered the row, so each slice counts it once.
  std::vector<uint32_t> seenBy(table.rowCount(), kLoopNone);
  uint32_t first = 0;
  for (const uint32_t end : table.batchEnds) {
    StencilSlice slice{first, 0, 0, 0};
    for (uint32_t s = first; s < end;) {
      const uint32_t id = uint32_t(slices.size());
      uint32_t newRows = 0;
      for (uint32_t j = table.offsets[s]; j < table.offsets[s + 1]; ++j)
        if (seenBy[table.indices[j]] != id) seenBy[table.indices[j]] = id, ++newRows;
      const uint32_t entries = table.offsets[s + 1] - table.offsets[s];
      const char* array = nullptr;
      if (fits(slice.stencilCount + 1, uint64_t(slice.entryCount) + entries,
               uint64_t(slice.gatheredRows) + newRows, width, maxArrayBytes, &array)) {
        ++slice.stencilCount;
        slice.entryCount += entries;
        slice.gatheredRows += newRows;
        ++s;
        continue;
      }
      if (slice.stencilCount == 0)
        throw LimitError("Loop stencils: stencil " + std::to_string(s) + " alone needs more " +
                         array + " than the " + std::to_string(maxArrayBytes) +
                         " bytes one device array may hold");
      // Close the slice; stencil s starts the next one and is counted again under the new id
      // (its marks under the old id do not match it).
      slices.push_back(slice);
      slice = StencilSlice{s, 0, 0, 0};
    }
    if (slice.stencilCount > 0) slices.push_back(slice);
    first = end;
  }
  return slices;
}

void gatherStencilSlice(const FloatStencilTable& table, const StencilSlice& slice,
                        const float* rows, uint32_t width, std::vector<uint32_t>& localRow,
                        uint32_t* offsets, uint32_t* indices, float* weights, float* values) {
  const uint32_t base = table.offsets[slice.firstStencil];
  for (uint32_t i = 0; i <= slice.stencilCount; ++i)
    offsets[i] = table.offsets[slice.firstStencil + i] - base;
  uint32_t gathered = 0;
  for (uint32_t j = 0; j < slice.entryCount; ++j) {
    const uint32_t row = table.indices[base + j];
    if (localRow[row] == kLoopNone) {
      localRow[row] = gathered;
      std::memcpy(values + size_t(gathered) * width, rows + size_t(row) * width,
                  width * sizeof(float));
      ++gathered;
    }
    indices[j] = localRow[row];
  }
  std::memcpy(weights, table.weights.data() + base, slice.entryCount * sizeof(float));
  for (uint32_t j = 0; j < slice.entryCount; ++j) localRow[table.indices[base + j]] = kLoopNone;
}

}  // namespace tessera
