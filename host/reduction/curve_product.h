// The one matrix product of the control-point reduction: a band matrix (A⁺, banded_oslo.h)
// applied to every curve of one direction of a net. Backends share this interface so the
// reduction and the tests can swap them: double on the CPU (the reference), the fp32 mirror
// on the CPU, and fp32 on the GPU (shaders/reduction_apply.comp.glsl).
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "reduction/banded_oslo.h"

namespace tessera {

namespace vk {
class Context;
}

class CurveProduct {
 public:
  virtual ~CurveProduct() = default;
  virtual std::string name() const = 0;
  // out (curves × m.rows) = m applied to each curve of `in` (curves × m.cols), row-major.
  // Throws std::invalid_argument when the sizes do not match.
  virtual std::vector<glm::dvec3> apply(const BandMatrix& m, const std::vector<glm::dvec3>& in,
                                        int curves) = 0;
};

// applyBandToCurves in double.
std::unique_ptr<CurveProduct> makeReferenceCurveProduct();

// What the fp32 backends compute on: the band in fp32, and each curve relative to its own first
// point (subtracted in double), so the rounding is relative to the curve's extent, not to its
// distance from the origin. unpack adds first point · Σ_t w_t back in double. Error bound per
// output point against double: 2·(width + 1)·2⁻²⁴·Σ_t|w_t|·max_t|P_t − P_first| (fp32 rounding
// of the weights, the points and each of the `width` sums), tests/test_reduction_gpu.cpp.
struct PackedCurves {
  uint32_t rows = 0, cols = 0, curves = 0;
  std::vector<uint32_t> firsts, offsets;  // rows, rows + 1
  std::vector<float> weights;
  std::vector<glm::vec4> points;  // curves × cols, xyz relative, w = 0
  std::vector<glm::dvec3> bases;  // each curve's first point
  std::vector<double> rowSums;    // Σ_t w_t of each row, in double
};
PackedCurves packCurves(const BandMatrix& m, const std::vector<glm::dvec3>& in, int curves);
// results: curves × rows points as the shader wrote them.
std::vector<glm::dvec3> unpackCurves(const PackedCurves& packed,
                                     const std::vector<glm::vec4>& results);

// The fp32 mirror of the shader on the CPU (host/reduction/detail/band_mirror.h).
std::unique_ptr<CurveProduct> makeMirrorCurveProduct();

// fp32 on the GPU; buffers grow to the largest product seen. Throws std::length_error when a
// product exceeds the device's storage buffer range.
std::unique_ptr<CurveProduct> makeVulkanCurveProduct(vk::Context& context);

}  // namespace tessera
