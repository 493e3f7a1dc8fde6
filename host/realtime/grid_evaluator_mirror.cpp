// The fp32 mirror backend of GridEvaluator: rows shared out to threads, the same arithmetic as
// shaders/grid_eval.comp.glsl.
#include "realtime/grid_evaluator.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <thread>

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
  explicit MirrorGridEvaluator(unsigned threads)
      : threads_(threads ? threads : std::max(1u, std::thread::hardware_concurrency())) {}

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
    if (threads_ == 1 || rows < 2) {
      work(0, rows);
      return out_.data();
    }
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads_; ++t)
      pool.emplace_back(work, rows * t / threads_, rows * (t + 1) / threads_);
    for (auto& thread : pool) thread.join();
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
