#include "quadtree/tolerance.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "geometry/model_frame.h"

namespace tessera {
namespace {

// The whole of `text` as a finite double, or NaN (strtod alone accepts "1e3x" up to the x).
double wholeNumber(const std::string& text) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text.front())))
    return std::nan("");
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(value)) return std::nan("");
  return value;
}

}  // namespace

ToleranceSpec parseTolerance(const std::string& text) {
  if (text.size() > 2 && text.compare(text.size() - 2, 2, "px") == 0) {
    const double pixels = wholeNumber(text.substr(0, text.size() - 2));
    if (!(pixels > 0))
      throw std::invalid_argument("the tolerance '" + text + "' is not a number of pixels > 0");
    ToleranceSpec spec;
    spec.text = text;
    spec.relative = false;
    spec.pixels = true;
    spec.value = pixels;
    return spec;
  }
  const bool relative = !text.empty() && text.back() == '%';
  const double number = wholeNumber(relative ? text.substr(0, text.size() - 1) : text);
  ToleranceSpec spec;
  spec.text = text;
  spec.relative = relative;
  if (relative) {
    if (!(number > 0 && number <= 100))
      throw std::invalid_argument("the tolerance '" + text +
                                  "' is not a percentage of the model's size in (0%, 100%]");
    spec.value = number / 100.0;
  } else {
    if (!(number > 0))
      throw std::invalid_argument("the tolerance '" + text +
                                  "' is not a distance > 0 in model units (or a percentage "
                                  "such as 0.1%)");
    spec.value = number;
  }
  return spec;
}

double controlPointDiagonal(const std::vector<BezierPatch>& patches) {
  const ControlPointBox box = controlPointBox(patches);
  // hypot, not the length's squares: the model at 10⁻³⁰⁰ has a diagonal too.
  const glm::dvec3 extent = box.hi - box.lo;
  const double diagonal = box.empty ? 0.0 : std::hypot(extent.x, extent.y, extent.z);
  if (!(diagonal > 0) || !std::isfinite(diagonal))
    throw std::invalid_argument(
        "a relative tolerance needs a model of nonzero size (the control points' bounding box "
        "has diagonal " + std::to_string(diagonal) + ")");
  return diagonal;
}

double resolveTolerance(const ToleranceSpec& spec, const std::vector<BezierPatch>& patches) {
  if (spec.pixels)
    throw std::invalid_argument("the tolerance '" + spec.text +
                                "' is in pixels: it needs a camera (a view and a viewport)");
  return spec.relative ? spec.value * controlPointDiagonal(patches) : spec.value;
}

std::string describeTolerance(const ToleranceSpec& spec, double resolved) {
  char text[160];
  if (spec.pixels)
    std::snprintf(text, sizeof text, "%.4g px", resolved);
  else if (spec.relative)
    std::snprintf(text, sizeof text, "%.4g (%s of the diagonal %.4g)", resolved, spec.text.c_str(),
                  resolved / spec.value);
  else
    std::snprintf(text, sizeof text, "%.4g", resolved);
  return text;
}

double largestLeafBound(const QuadtreeResult& tree) {
  double largest = 0;
  for (const QuadLeaf& leaf : tree.leaves) largest = std::max(largest, double(leaf.flatness));
  return largest * tree.boundScale;
}

}  // namespace tessera
