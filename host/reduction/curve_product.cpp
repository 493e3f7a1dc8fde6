#include "reduction/curve_product.h"

#include <stdexcept>

#include "reduction/detail/band_mirror.h"

namespace tessera {

namespace {

class ReferenceCurveProduct final : public CurveProduct {
 public:
  std::string name() const override { return "cpu (double)"; }
  std::vector<glm::dvec3> apply(const BandMatrix& m, const std::vector<glm::dvec3>& in,
                                int curves) override {
    return applyBandToCurves(m, in, curves);
  }
};

class MirrorCurveProduct final : public CurveProduct {
 public:
  std::string name() const override { return "cpu (fp32 mirror)"; }
  std::vector<glm::dvec3> apply(const BandMatrix& m, const std::vector<glm::dvec3>& in,
                                int curves) override {
    const PackedCurves packed = packCurves(m, in, curves);
    std::vector<glm::vec4> results(static_cast<size_t>(packed.curves) * packed.rows);
    mirror::applyBandRows(packed.firsts.data(), packed.offsets.data(), packed.weights.data(),
                          packed.points.data(), results.data(), packed.rows, packed.cols,
                          packed.curves);
    return unpackCurves(packed, results);
  }
};

}  // namespace

std::unique_ptr<CurveProduct> makeReferenceCurveProduct() { return std::make_unique<ReferenceCurveProduct>(); }
std::unique_ptr<CurveProduct> makeMirrorCurveProduct() {
  return std::make_unique<MirrorCurveProduct>();
}

PackedCurves packCurves(const BandMatrix& m, const std::vector<glm::dvec3>& in, int curves) {
  if (curves < 0 || in.size() != static_cast<size_t>(curves) * static_cast<size_t>(m.cols)) {
    throw std::invalid_argument("curve product: " + std::to_string(in.size()) +
                                " points are not " + std::to_string(curves) + " curves of " +
                                std::to_string(m.cols));
  }
  PackedCurves p;
  p.rows = static_cast<uint32_t>(m.rows);
  p.cols = static_cast<uint32_t>(m.cols);
  p.curves = static_cast<uint32_t>(curves);
  p.firsts.assign(m.first.begin(), m.first.end());
  p.offsets.assign(m.offset.begin(), m.offset.end());
  p.weights.assign(m.values.begin(), m.values.end());
  for (int i = 0; i < m.rows; ++i) {
    double sum = 0.0;
    for (size_t k = m.offset[static_cast<size_t>(i)]; k < m.offset[static_cast<size_t>(i) + 1]; ++k) {
      sum += m.values[k];
    }
    p.rowSums.push_back(sum);
  }
  p.points.resize(in.size());
  p.bases.resize(static_cast<size_t>(curves));
  for (size_t c = 0; c < p.bases.size(); ++c) {
    const size_t start = c * p.cols;
    p.bases[c] = p.cols > 0 ? in[start] : glm::dvec3(0.0);
    for (size_t t = 0; t < p.cols; ++t) p.points[start + t] = glm::vec4(glm::vec3(in[start + t] - p.bases[c]), 0.0f);
  }
  return p;
}

std::vector<glm::dvec3> unpackCurves(const PackedCurves& p, const std::vector<glm::vec4>& results) {
  std::vector<glm::dvec3> out(static_cast<size_t>(p.curves) * p.rows);
  for (size_t c = 0; c < p.curves; ++c) {
    for (size_t i = 0; i < p.rows; ++i) {
      out[c * p.rows + i] = p.bases[c] * p.rowSums[i] + glm::dvec3(glm::vec3(results[c * p.rows + i]));
    }
  }
  return out;
}

}  // namespace tessera
