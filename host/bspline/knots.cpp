#include "bspline/knots.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "geometry/patch.h"

namespace tessera {

namespace {

[[noreturn]] void reject(const char* what, const std::string& reason) {
  throw std::invalid_argument(std::string(what) + ": " + reason);
}

void checkDegreeAndCount(int degree, int controlCount, const char* what) {
  if (degree < 1 || degree > kMaxDegree) {
    reject(what, "degree " + std::to_string(degree) + " is outside [1, " +
                     std::to_string(kMaxDegree) + "]");
  }
  if (controlCount < degree + 1) {
    reject(what, "degree " + std::to_string(degree) + " needs at least " +
                     std::to_string(degree + 1) + " control points, got " +
                     std::to_string(controlCount));
  }
}

}  // namespace

std::vector<double> uniformKnots(int degree, int controlCount, double first, double spacing) {
  checkDegreeAndCount(degree, controlCount, "uniformKnots");
  if (!(spacing > 0.0) || !std::isfinite(spacing) || !std::isfinite(first)) {
    reject("uniformKnots", "spacing must be finite and positive");
  }
  std::vector<double> knots(static_cast<size_t>(controlCount + degree + 1));
  // first + i·spacing rather than a running sum, so no rounding drift along the vector.
  for (size_t i = 0; i < knots.size(); ++i) knots[i] = first + static_cast<double>(i) * spacing;
  return knots;
}

std::vector<double> openUniformKnots(int degree, int controlCount, double a, double b) {
  checkDegreeAndCount(degree, controlCount, "openUniformKnots");
  if (!(a < b) || !std::isfinite(a) || !std::isfinite(b)) {
    reject("openUniformKnots", "needs finite a < b");
  }
  const int pieces = controlCount - degree;
  std::vector<double> knots;
  knots.reserve(static_cast<size_t>(controlCount + degree + 1));
  knots.insert(knots.end(), static_cast<size_t>(degree + 1), a);
  for (int i = 1; i < pieces; ++i) knots.push_back(a + (b - a) * i / pieces);
  knots.insert(knots.end(), static_cast<size_t>(degree + 1), b);
  return knots;
}

void validateKnots(int degree, int controlCount, const std::vector<double>& knots,
                   const char* what) {
  checkDegreeAndCount(degree, controlCount, what);
  const size_t expected = static_cast<size_t>(controlCount + degree + 1);
  if (knots.size() != expected) {
    std::ostringstream msg;
    msg << "wrong length: expected " << expected << " knots (" << controlCount
        << " control points + degree " << degree << " + 1), got " << knots.size();
    reject(what, msg.str());
  }
  for (size_t i = 0; i < knots.size(); ++i) {
    if (!std::isfinite(knots[i])) reject(what, "knot " + std::to_string(i) + " is not finite");
  }
  int run = 1;
  for (size_t i = 1; i < knots.size(); ++i) {
    if (knots[i] < knots[i - 1]) {
      std::ostringstream msg;
      msg << "knots must be non-decreasing, but x_" << i - 1 << " = " << knots[i - 1] << " > x_"
          << i << " = " << knots[i];
      reject(what, msg.str());
    }
    run = knots[i] == knots[i - 1] ? run + 1 : 1;
    if (run > degree + 1) {
      std::ostringstream msg;
      msg << "multiplicity of knot " << knots[i] << " exceeds degree + 1 = " << degree + 1;
      reject(what, msg.str());
    }
  }
  if (!(knots[static_cast<size_t>(degree)] < knots[static_cast<size_t>(controlCount)])) {
    std::ostringstream msg;
    msg << "empty parameter domain [x_" << degree << ", x_" << controlCount << "] = ["
        << knots[static_cast<size_t>(degree)] << ", " << knots[static_cast<size_t>(controlCount)]
        << "]";
    reject(what, msg.str());
  }
}

int knotMultiplicity(const std::vector<double>& knots, double value) {
  return static_cast<int>(std::count(knots.begin(), knots.end(), value));
}

int findSpan(int degree, const std::vector<double>& knots, double t) {
  if (!std::isfinite(t)) throw std::invalid_argument("findSpan: parameter is not finite");
  const auto first = knots.begin();
  const int n = static_cast<int>(knots.size()) - degree - 1;
  const double lo = knots[static_cast<size_t>(degree)];
  const double hi = knots[static_cast<size_t>(n)];
  // Binary search over knot values: the result is the last index of a run of equal knots,
  // so repeated knots never yield an empty span.
  if (t >= hi) return static_cast<int>(std::lower_bound(first, knots.end(), hi) - first) - 1;
  if (t < lo) return static_cast<int>(std::upper_bound(first, knots.end(), lo) - first) - 1;
  return static_cast<int>(std::upper_bound(first, knots.end(), t) - first) - 1;
}

}  // namespace tessera
