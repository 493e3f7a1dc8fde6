// The one matrix product of the control-point reduction: a band matrix (A⁺, banded_oslo.h)
// applied to every curve of one direction of a net. Backends share this interface so the
// reduction and the tests can swap them: double on the CPU (the reference) and fp32 on the GPU.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "banded_oslo.h"

namespace tessera {

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
std::unique_ptr<CurveProduct> makeCpuCurveProduct();

}  // namespace tessera
