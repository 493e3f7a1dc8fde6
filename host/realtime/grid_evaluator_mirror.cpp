// The fp32 mirror backend of GridEvaluator: rows shared out to threads, the same arithmetic as
// shaders/grid_eval.comp.glsl.
#include "realtime/grid_evaluator.h"

#include <stdexcept>
#include <string>

#include "common/parallel_for.h"
#include "eval/evaluator.h"
#include "realtime/detail/grid_mirror.h"

namespace tessera {

void validateGridPointsPerSide(uint32_t pointsPerSide) {
  if (pointsPerSide < 2)
    throw std::invalid_argument("grid evaluation: points per side must be >= 2, got " +
                                std::to_string(pointsPerSide));
}

namespace {

class MirrorGridEvaluator final : public GridEvaluator {
 public:
  explicit MirrorGridEvaluator(unsigned threads) : threads_(resolveThreadCount(threads)) {}

  std::string name() const override {
    return threads_ == 1 ? "mirror" : "mirror x" + std::to_string(threads_);
  }

  const gpu::GridVertex* evaluate(const std::vector<gpu::BicubicPatch>& patches,
                                  uint32_t pointsPerSide) override {
    validateGridPointsPerSide(pointsPerSide);
    out_.resize(gridVertexCount(patches.size(), pointsPerSide));
    const size_t rows = patches.size() * pointsPerSide;
    auto work = [&](size_t first, size_t last) {
      for (size_t r = first; r < last; ++r)
        mirror::evalGridRow(patches[r / pointsPerSide], uint32_t(r % pointsPerSide),
                            pointsPerSide, kDegenerateEpsFp32, &out_[r * pointsPerSide]);
    };
    parallelFor(rows, threads_, work);
    return out_.data();
  }

 private:
  unsigned threads_;
  std::vector<gpu::GridVertex> out_;
};

}  // namespace

std::unique_ptr<GridEvaluator> makeMirrorGridEvaluator(unsigned threads) {
  return std::make_unique<MirrorGridEvaluator>(threads);
}

}  // namespace tessera
