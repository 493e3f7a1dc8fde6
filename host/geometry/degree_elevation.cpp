#include "geometry/degree_elevation.h"

#include <stdexcept>
#include <string>

#include "geometry/bezier.h"

namespace tessera {
namespace {

// One elevation step along a line of n + 1 points spaced `stride` apart in `in`, written as
// n + 2 points spaced `outStride` apart in `out`.
void elevateLine(const glm::dvec3* in, size_t stride, int n, glm::dvec3* out, size_t outStride) {
  // Both weights as exact quotients of integers, not a and 1 − a: the reversed curve then
  // gets the same products, so a boundary shared in opposite directions stays bit-identical.
  const double denominator = n + 1;
  out[0] = in[0];
  for (int i = 1; i <= n; ++i) {
    const double previous = i / denominator;
    const double current = (n + 1 - i) / denominator;
    out[i * outStride] = previous * in[(i - 1) * stride] + current * in[i * stride];
  }
  out[(n + 1) * outStride] = in[n * stride];
}

void checkElevatable(const BezierPatch& patch, int degree, const char* where) {
  validatePatch(patch);
  if (degree + 1 > kMaxDegree)
    throw std::invalid_argument(std::string(where) + ": degree " + std::to_string(degree) +
                                " cannot be raised above " + std::to_string(kMaxDegree));
}

}  // namespace

BezierPatch elevateDegreeU(const BezierPatch& patch) {
  checkElevatable(patch, patch.degreeU, "elevateDegreeU");
  BezierPatch out;
  out.degreeU = patch.degreeU + 1;
  out.degreeV = patch.degreeV;
  out.cp.resize(static_cast<size_t>((out.degreeU + 1) * (out.degreeV + 1)));
  const size_t columns = static_cast<size_t>(patch.degreeV + 1);
  // Columns j run along u: consecutive points are a whole row apart.
  for (size_t j = 0; j < columns; ++j)
    elevateLine(&patch.cp[j], columns, patch.degreeU, &out.cp[j], columns);
  return out;
}

BezierPatch elevateDegreeV(const BezierPatch& patch) {
  checkElevatable(patch, patch.degreeV, "elevateDegreeV");
  BezierPatch out;
  out.degreeU = patch.degreeU;
  out.degreeV = patch.degreeV + 1;
  out.cp.resize(static_cast<size_t>((out.degreeU + 1) * (out.degreeV + 1)));
  const size_t inRow = static_cast<size_t>(patch.degreeV + 1);
  const size_t outRow = static_cast<size_t>(out.degreeV + 1);
  for (int i = 0; i <= patch.degreeU; ++i)
    elevateLine(&patch.cp[i * inRow], 1, patch.degreeV, &out.cp[i * outRow], 1);
  return out;
}

BezierPatch elevateDegreeTo(const BezierPatch& patch, int degreeU, int degreeV) {
  validatePatch(patch);
  if (degreeU < patch.degreeU || degreeV < patch.degreeV || degreeU > kMaxDegree ||
      degreeV > kMaxDegree)
    throw std::invalid_argument("elevateDegreeTo: cannot take degree " +
                                std::to_string(patch.degreeU) + "×" +
                                std::to_string(patch.degreeV) + " to " + std::to_string(degreeU) +
                                "×" + std::to_string(degreeV));
  BezierPatch out = patch;
  while (out.degreeU < degreeU) out = elevateDegreeU(out);
  while (out.degreeV < degreeV) out = elevateDegreeV(out);
  return out;
}

}  // namespace tessera
