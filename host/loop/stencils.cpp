#include "loop/stencils.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

#include "common/memory_budget.h"
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

uint64_t estimatedLoopStencilBytes(size_t baseFaces, const LoopStencilOptions& options) {
  // Counts on a closed triangle mesh (Euler: E = 3F/2, V ≈ F/2; boundaries change little):
  // level l has F·4^l faces. Bytes per face of one level's LoopTopology, from its arrays:
  // triangles 3 u32, edgeVertices and edgeFaces 1.5 pairs each, faceEdges 3 u32, edge flags
  // 1.5 × 2 bytes, rings 2E = 3F entries of vertex and edge (u32 each), and per vertex an
  // offset, two flags and a rule.
  const double topologyPerFace =
      3.0 * sizeof(uint32_t) + 1.5 * 2 * sizeof(std::array<uint32_t, 2>) + 3.0 * sizeof(uint32_t) +
      1.5 * 2 + 3.0 * 2 * sizeof(uint32_t) +
      0.5 * (sizeof(uint32_t) + 2 + sizeof(LoopVertexRule));
  // The stencils that make level l + 1 from level l: V_l vertex masks of valence + 1 ≈ 7
  // entries and E_l edge masks of 4, i.e. 9.5 F_l entries of an index and a double weight,
  // plus 2 F_l offsets; the fp32 copy for the evaluators repeats them with float weights.
  const double stencilPerFace = 9.5 * (2 * sizeof(uint32_t) + sizeof(double) + sizeof(float)) +
                                2.0 * 2 * sizeof(uint32_t);
  // Limit positions (valence + 1 ≈ 7 entries) and two tangents (≈ 6 each) per vertex of the
  // last level, in double and fp32.
  const double limitPerFace =
      0.5 * ((options.limit ? 7 : 0) + (options.tangents ? 12 : 0)) *
      (2 * sizeof(uint32_t) + sizeof(double) + sizeof(float));
  // The evaluators' rows (3 floats per row of every level) and the output: double positions,
  // the float TriangleMesh and its indices, per vertex (V = F/2) or face of the last level.
  const double rowsAndOutputPerFace =
      0.5 * (3 * sizeof(float) + sizeof(double) * 3 + sizeof(float) * 3 * (options.limit ? 2 : 1)) +
      2 * 3 * sizeof(uint32_t);
  double before = 0, faces = double(baseFaces);  // faces of levels 0 .. L − 1; of level L
  for (int level = 0; level < options.levels && faces < 1e30; ++level) {
    before += faces;
    faces *= 4;
  }
  // × 1.3: the vectors grow by doubling as masks are appended, so they hold more than their
  // size (measured on the torus at level 6: 586 MiB peak resident for loop, 1,289 MiB for
  // limit, against 694 and 1,268 MiB estimated).
  const double bytes = 1.3 * ((before + faces) * topologyPerFace + before * stencilPerFace +
                              faces * (limitPerFace + rowsAndOutputPerFace) +
                              4.0 / 3.0 * faces * 12);
  return bytes >= 1.8e19 ? UINT64_MAX : uint64_t(bytes);
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
  requireWithinMemoryBudget(
      estimatedLoopStencilBytes(base.faceCount(), options),
      "Loop subdivision of " + std::to_string(base.faceCount()) + " triangles to level " +
          std::to_string(options.levels) + " (" + std::to_string(base.faceCount()) + " × 4^" +
          std::to_string(options.levels) + " triangles)");
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
