#include "curve_product.h"

namespace tessera {

namespace {

class CpuCurveProduct final : public CurveProduct {
 public:
  std::string name() const override { return "cpu (double)"; }
  std::vector<glm::dvec3> apply(const BandMatrix& m, const std::vector<glm::dvec3>& in,
                                int curves) override {
    return applyBandToCurves(m, in, curves);
  }
};

}  // namespace

std::unique_ptr<CurveProduct> makeCpuCurveProduct() { return std::make_unique<CpuCurveProduct>(); }

}  // namespace tessera
