#include "loop/stencils.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "loop/limit.h"

namespace tessera {
namespace {

// Rewrites every stencil in terms of the source rows only: a stencil that reads row r ≥
// sourceRows reads, instead, the (already factorized) stencil that wrote r.
StencilTable factorized(const StencilTable& chained) {
  StencilTable out;
  out.sourceRows = chained.sourceRows;
  std::vector<double> accumulator(chained.sourceRows, 0.0);
  std::vector<uint8_t> marked(chained.sourceRows, 0);
  std::vector<uint32_t> touched;
  for (size_t s = 0; s < chained.stencilCount(); ++s) {
    touched.clear();
    auto add = [&](uint32_t row, double weight) {
      if (!marked[row]) marked[row] = 1, touched.push_back(row);
      accumulator[row] += weight;
    };
    for (uint32_t j = chained.offsets[s]; j < chained.offsets[s + 1]; ++j) {
      const uint32_t row = chained.indices[j];
      const double weight = chained.weights[j];
      if (row < chained.sourceRows) {
        add(row, weight);
        continue;
      }
      const size_t source = row - chained.sourceRows;  // < s: written by an earlier stencil
      for (uint32_t i = out.offsets[source]; i < out.offsets[source + 1]; ++i)
        add(out.indices[i], weight * out.weights[i]);
    }
    std::sort(touched.begin(), touched.end());
    for (uint32_t row : touched) {
      const double weight = accumulator[row];
      accumulator[row] = 0.0;
      marked[row] = 0;
      if (weight == 0.0) continue;
      out.indices.push_back(row);
      out.weights.push_back(weight);
    }
    out.offsets.push_back(uint32_t(out.indices.size()));
  }
  out.endBatch();
  return out;
}

}  // namespace

void StencilTable::append(const LoopMask& mask, uint32_t rowOffset) {
  for (size_t j = 0; j < mask.size(); ++j) {
    indices.push_back(rowOffset + mask.indices[j]);
    weights.push_back(mask.weights[j]);
  }
  offsets.push_back(uint32_t(indices.size()));
}

FloatStencilTable toFloatStencils(const StencilTable& table) {
  FloatStencilTable out;
  out.sourceRows = table.sourceRows;
  out.offsets = table.offsets;
  out.indices = table.indices;
  out.weights.assign(table.weights.begin(), table.weights.end());
  out.batchEnds = table.batchEnds;
  return out;
}

LoopStencils buildLoopStencils(const LoopTopology& base, const LoopStencilOptions& options) {
  if (options.levels < 0)
    throw std::invalid_argument("buildLoopStencils: negative level count " +
                                std::to_string(options.levels));
  LoopStencils out;
  StencilTable& table = out.table;
  table.sourceRows = base.vertexCount;
  out.topology.push_back(base);
  out.levelRow.push_back(0);
  LoopMask mask;
  for (int level = 0; level < options.levels; ++level) {
    const LoopTopology& t = out.topology.back();
    const uint32_t row = out.levelRow.back();
    for (uint32_t v = 0; v < t.vertexCount; ++v) {
      loopVertexMask(t, v, mask);
      table.append(mask, row);
    }
    for (uint32_t e = 0; e < t.edgeCount(); ++e) {
      loopEdgeMask(t, e, mask);
      table.append(mask, row);
    }
    table.endBatch();
    out.levelRow.push_back(row + t.vertexCount);
    out.topology.push_back(refineLoopTopology(t));
  }
  const LoopTopology& last = out.topology.back();
  const uint32_t lastRow = out.levelRow.back();
  uint32_t nextRow = lastRow + last.vertexCount;
  if (options.limit) {
    out.limitRow = nextRow;
    nextRow += last.vertexCount;
    for (uint32_t v = 0; v < last.vertexCount; ++v) {
      loopLimitMask(last, v, mask);
      table.append(mask, lastRow);
    }
  }
  if (options.tangents) {
    LoopMask second;
    out.tangent1Row = nextRow;
    out.tangent2Row = nextRow + last.vertexCount;
    for (int which = 0; which < 2; ++which)
      for (uint32_t v = 0; v < last.vertexCount; ++v) {
        loopLimitTangentMasks(last, v, mask, second);
        table.append(which == 0 ? mask : second, lastRow);
      }
  }
  if (options.limit || options.tangents) table.endBatch();
  if (options.factorize) table = factorized(table);
  return out;
}

void applyStencils(const StencilTable& table, std::vector<double>& rows, uint32_t width) {
  if (rows.size() != table.rowCount() * width)
    throw std::invalid_argument("applyStencils: " + std::to_string(rows.size()) +
                                " values for " + std::to_string(table.rowCount()) +
                                " rows of width " + std::to_string(width));
  for (size_t s = 0; s < table.stencilCount(); ++s) {
    double* out = &rows[(table.sourceRows + s) * width];
    for (uint32_t c = 0; c < width; ++c) out[c] = 0.0;
    for (uint32_t j = table.offsets[s]; j < table.offsets[s + 1]; ++j) {
      const double* in = &rows[size_t(table.indices[j]) * width];
      for (uint32_t c = 0; c < width; ++c) out[c] += table.weights[j] * in[c];
    }
  }
}

}  // namespace tessera
