// Packing for the division-count shader and the fp32 mirror backend of DivisionCounter
// (the shader's twin: the same arithmetic as shaders/division_count.comp.glsl, one patch a call).
#include "division/counter.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "division/detail/count_mirror.h"

namespace tessera {

DivisionBatch packDivisionBatch(const std::vector<RationalBezierPatch>& patches) {
  DivisionBatch batch;
  batch.patches.reserve(patches.size());
  for (size_t p = 0; p < patches.size(); ++p) {
    try {
      validateDivisionInput(patches[p], DivisionMethod::Split);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("patch " + std::to_string(p) + ": " + e.what());
    }
    batch.patches.push_back({static_cast<uint32_t>(batch.points.size()),
                             static_cast<uint32_t>(patches[p].degreeU),
                             static_cast<uint32_t>(patches[p].degreeV), 0u});
    for (const glm::dvec4& h : patches[p].cpw) batch.points.push_back(gpu::vec4(h));
  }
  return batch;
}

void appendDivisionCurves(DivisionBatch& batch, const std::vector<RationalBezierCurve>& curves) {
  for (size_t c = 0; c < curves.size(); ++c) {
    try {
      validateDivisionInput(curves[c], DivisionMethod::Split);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("curve " + std::to_string(c) + ": " + e.what());
    }
    batch.patches.push_back({static_cast<uint32_t>(batch.points.size()),
                             static_cast<uint32_t>(curves[c].degree), 0u, 0u});
    for (const glm::dvec4& h : curves[c].cpw) batch.points.push_back(gpu::vec4(h));
  }
}

gpu::DivisionPush divisionPush(const DivisionOptions& options, size_t patchCount) {
  if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance))
    throw std::invalid_argument("division count: the tolerance must be a finite number > 0");
  if (options.maxPerDirection < 1 || options.ratioPieces < 1 || options.ratioPieces > 64)
    throw std::invalid_argument("division count: need maxPerDirection ≥ 1 and 1 ≤ q ≤ 64");
  if (options.zeroClassThreshold != 0.0 || options.method != DivisionMethod::Split)
    throw std::invalid_argument("division count: the GPU runs the split method, exact zeros only");
  return {static_cast<float>(options.tolerance), static_cast<uint32_t>(options.maxPerDirection),
          static_cast<uint32_t>(options.ratioPieces), static_cast<uint32_t>(patchCount)};
}

namespace {

class MirrorDivisionCounter final : public DivisionCounter {
 public:
  std::vector<gpu::DivisionResult> count(const DivisionBatch& batch,
                                         const DivisionOptions& options) override {
    const gpu::DivisionPush push = divisionPush(options, batch.patches.size());
    std::vector<gpu::DivisionResult> out(batch.patches.size());
    for (size_t p = 0; p < out.size(); ++p)
      out[p] = mirror::divisionCounts(batch.patches[p],
                                      batch.points.data() + batch.patches[p].firstPoint, push);
    return out;
  }
};

}  // namespace

std::unique_ptr<DivisionCounter> makeMirrorDivisionCounter() {
  return std::make_unique<MirrorDivisionCounter>();
}

}  // namespace tessera
