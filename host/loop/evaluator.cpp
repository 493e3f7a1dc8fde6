// The CPU backends of StencilEvaluator: double (the reference) and the fp32 mirror.
#include "loop/evaluator.h"

#include <stdexcept>

#include "loop/detail/stencil_mirror.h"

namespace tessera {
namespace {

class ReferenceStencilEvaluator final : public StencilEvaluator {
 public:
  ReferenceStencilEvaluator(const StencilTable& table, uint32_t width) : table_(table), width_(width) {}
  std::string name() const override { return "cpu double"; }
  void apply(std::vector<float>& rows) override {
    checkStencilRows(table_.rowCount(), width_, rows.size());
    scratch_.assign(rows.begin(), rows.end());
    applyStencils(table_, scratch_, width_);
    const size_t first = size_t(table_.sourceRows) * width_;
    for (size_t i = first; i < rows.size(); ++i) rows[i] = float(scratch_[i]);
  }

 private:
  StencilTable table_;
  uint32_t width_;
  std::vector<double> scratch_;
};

class MirrorStencilEvaluator final : public StencilEvaluator {
 public:
  MirrorStencilEvaluator(const FloatStencilTable& table, uint32_t width)
      : table_(table), width_(width) {}
  std::string name() const override { return "cpu fp32 mirror"; }
  void apply(std::vector<float>& rows) override {
    checkStencilRows(table_.rowCount(), width_, rows.size());
    mirror::applyStencils(table_.offsets.data(), table_.indices.data(), table_.weights.data(),
                          rows.data(), 0, uint32_t(table_.stencilCount()), table_.sourceRows,
                          width_);
  }

 private:
  FloatStencilTable table_;
  uint32_t width_;
};

}  // namespace

void checkStencilRows(size_t rowCount, uint32_t width, size_t values) {
  if (width == 0) throw std::invalid_argument("stencil evaluator: row width 0");
  if (values != rowCount * width)
    throw std::invalid_argument("stencil evaluator: " + std::to_string(values) +
                                " values for " + std::to_string(rowCount) + " rows of width " +
                                std::to_string(width));
}

std::unique_ptr<StencilEvaluator> makeReferenceStencilEvaluator(const StencilTable& table,
                                                          uint32_t width) {
  return std::make_unique<ReferenceStencilEvaluator>(table, width);
}

std::unique_ptr<StencilEvaluator> makeMirrorStencilEvaluator(const FloatStencilTable& table,
                                                             uint32_t width) {
  return std::make_unique<MirrorStencilEvaluator>(table, width);
}

}  // namespace tessera
