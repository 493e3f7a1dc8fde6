#include "scene_convert.h"

#include <string>

#include "bezier.h"
#include "bspline.h"
#include "bspline_to_bezier.h"
#include "degree_elevation.h"
#include "io/errors.h"

namespace tessera {
namespace {

constexpr int kTessellatorDegree = 3;
const char* const kLimitation = "the tessellator takes polynomial patches up to bicubic for now";

// The surfaces of a scene built in code, in the documented default order.
std::vector<SceneSurfaceRef> defaultOrder(const Scene& scene) {
  std::vector<SceneSurfaceRef> order;
  auto append = [&](SceneSurfaceType type, size_t count) {
    for (size_t k = 0; k < count; ++k) {
      SceneSurfaceRef ref;
      ref.type = type;
      ref.index = k;
      order.push_back(ref);
    }
  };
  append(SceneSurfaceType::Bezier, scene.bezier.size());
  append(SceneSurfaceType::Rational, scene.rational.size());
  append(SceneSurfaceType::BSpline, scene.bsplines.size());
  return order;
}

class Converter {
 public:
  explicit Converter(const Scene& scene)
      : scene_(scene), source_(scene.source.empty() ? "scene" : scene.source) {}

  void add(const SceneSurfaceRef& ref, size_t number) {
    const std::string where = "surface " + std::to_string(number) +
                              (ref.name.empty() ? "" : " (\"" + ref.name + "\")");
    switch (ref.type) {
      case SceneSurfaceType::Bezier:
        addPolynomial(scene_.bezier.at(ref.index), ref, where);
        break;
      case SceneSurfaceType::Rational:
        addPolynomial(polynomialOf(scene_.rational.at(ref.index), ref, where), ref, where);
        break;
      case SceneSurfaceType::BSpline: {
        const BSplineSurface& spline = scene_.bsplines.at(ref.index);
        checkDegree(spline.degreeU, spline.degreeV, ref, where);
        validateSurface(spline);
        for (const BezierPatchPiece& piece : bezierPatches(spline))
          addPolynomial(piece.patch, ref, where);
        break;
      }
    }
  }

  std::vector<BezierPatch> patches;

 private:
  void checkDegree(int degreeU, int degreeV, const SceneSurfaceRef& ref,
                   const std::string& where) const {
    if (degreeU > kTessellatorDegree || degreeV > kTessellatorDegree)
      throw InputError(InputErrorKind::Degree, source_, ref.degreeLine ? ref.degreeLine : ref.line,
                       std::string(kLimitation) + " (degree " + std::to_string(degreeU) + "×" +
                           std::to_string(degreeV) + " at " + where + ")");
  }

  void addPolynomial(const BezierPatch& patch, const SceneSurfaceRef& ref,
                     const std::string& where) {
    validatePatch(patch);
    checkDegree(patch.degreeU, patch.degreeV, ref, where);
    patches.push_back(elevateDegreeTo(patch, kTessellatorDegree, kTessellatorDegree));
  }

  // With every weight equal to w the quotient Σ B w b / Σ B w is Σ B b: a polynomial patch.
  BezierPatch polynomialOf(const RationalBezierPatch& rational, const SceneSurfaceRef& ref,
                           const std::string& where) const {
    BezierPatch patch;
    patch.degreeU = rational.degreeU;
    patch.degreeV = rational.degreeV;
    const double w = rational.cpw.empty() ? 0.0 : rational.cpw.front().w;
    for (const glm::dvec4& p : rational.cpw) {
      if (p.w != w || !(w > 0.0))
        throw InputError(InputErrorKind::Weight, source_,
                         ref.weightsLine ? ref.weightsLine : ref.line,
                         std::string(kLimitation) + " (rational weights at " + where +
                             "; only equal weights, which make the patch polynomial, are "
                             "accepted)");
      patch.cp.push_back(glm::dvec3(p) / w);
    }
    return patch;
  }

  const Scene& scene_;
  std::string source_;
};

}  // namespace

std::vector<BezierPatch> sceneToBicubicPatches(const Scene& scene) {
  const std::vector<SceneSurfaceRef> order = scene.order.empty() ? defaultOrder(scene) : scene.order;
  Converter converter(scene);
  for (size_t k = 0; k < order.size(); ++k) converter.add(order[k], k + 1);
  return std::move(converter.patches);
}

}  // namespace tessera
