#include "io/scene_convert.h"

#include <stdexcept>
#include <string>

#include "geometry/bezier.h"
#include "bspline/bspline.h"
#include "bspline/to_bezier.h"
#include "geometry/degree_elevation.h"
#include "geometry/general_patch.h"
#include "io/errors.h"
#include "io/quoted_token.h"
#include "geometry/rational.h"

namespace tessera {
namespace {

// Polynomial patches up to this degree are elevated to it, exactly, so that they take the
// bicubic fast path; higher degrees stay as they are (the general path takes them).
constexpr int kBicubic = 3;

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
                              (ref.name.empty() ? "" : " (" + quotedString(ref.name) + ")");
    switch (ref.type) {
      case SceneSurfaceType::Bezier:
        addPolynomial(scene_.bezier.at(ref.index));
        break;
      case SceneSurfaceType::Rational:
        addRational(scene_.rational.at(ref.index), ref, where);
        break;
      case SceneSurfaceType::BSpline: {
        const BSplineSurface& spline = scene_.bsplines.at(ref.index);
        validateSurface(spline);
        for (const BezierPatchPiece& piece : bezierPatches(spline)) addPolynomial(piece.patch);
        break;
      }
    }
  }

  std::vector<BezierPatch> patches;

 private:
  void addPolynomial(const BezierPatch& patch) {
    validatePatch(patch);
    patches.push_back(patch.degreeU <= kBicubic && patch.degreeV <= kBicubic
                          ? elevateDegreeTo(patch, kBicubic, kBicubic)
                          : patch);
  }

  // With every weight equal to w the quotient Σ B w b / Σ B w is Σ B b: a polynomial patch,
  // converted exactly. Otherwise the affine points b = (w·b)/w with their weights; a point of
  // weight 0 has no position (it drops out of the surface) and is kept as the origin.
  void addRational(const RationalBezierPatch& rational, const SceneSurfaceRef& ref,
                   const std::string& where) {
    validateRationalPatch(rational);
    BezierPatch patch;
    patch.degreeU = rational.degreeU;
    patch.degreeV = rational.degreeV;
    const double w0 = rational.cpw.front().w;
    bool equal = true;
    for (const glm::dvec4& h : rational.cpw) {
      patch.cp.push_back(h.w > 0.0 ? glm::dvec3(h) / h.w : glm::dvec3(0.0));
      patch.weights.push_back(h.w);
      equal = equal && h.w == w0;
    }
    if (equal) {
      patch.weights.clear();
      addPolynomial(patch);
      return;
    }
    try {  // the reader checks weights; a scene built in code may not have
      validateTessellationPatch(patch, where);
    } catch (const std::invalid_argument& e) {
      throw InputError(InputErrorKind::Weight, source_, ref.weightsLine ? ref.weightsLine : ref.line,
                       e.what());
    }
    patches.push_back(patch);
  }

  const Scene& scene_;
  std::string source_;
};

}  // namespace

std::vector<BezierPatch> sceneToPatches(const Scene& scene) {
  const std::vector<SceneSurfaceRef> order = scene.order.empty() ? defaultOrder(scene) : scene.order;
  Converter converter(scene);
  for (size_t k = 0; k < order.size(); ++k) converter.add(order[k], k + 1);
  return std::move(converter.patches);
}

}  // namespace tessera
