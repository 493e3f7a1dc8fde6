// a·x + b·y and s += a·x, one component at a time, for the hot loops of the double-precision
// references. glm's vector operators return `vec(x) op= y` by reference, and under
// AddressSanitizer each such copy stays a checked memcpy call (clang 14: 27 of them in
// tensorPartials<dvec4, 2>), which made the tests of those loops 17-28x slower than in
// Release. These do the same operations in the same order as glm's `a * x + b * y` and
// `s += a * x`, so every result is the same bit for bit.
#pragma once
#include <glm/glm.hpp>

namespace tessera {

inline void blendInto(double& out, double a, double x, double b, double y) { out = a * x + b * y; }
inline void addScaled(double& sum, double a, double x) { sum += a * x; }
inline void differenceInto(double& d, double next) { d = next - d; }

template <glm::length_t L, glm::qualifier Q>
void blendInto(glm::vec<L, double, Q>& out, double a, const glm::vec<L, double, Q>& x, double b,
               const glm::vec<L, double, Q>& y) {
  for (int c = 0; c < L; ++c) out[c] = a * x[c] + b * y[c];
}

template <glm::length_t L, glm::qualifier Q>
void addScaled(glm::vec<L, double, Q>& sum, double a, const glm::vec<L, double, Q>& x) {
  for (int c = 0; c < L; ++c) sum[c] += a * x[c];
}

// d = next − d, in place (a forward difference).
template <glm::length_t L, glm::qualifier Q>
void differenceInto(glm::vec<L, double, Q>& d, const glm::vec<L, double, Q>& next) {
  for (int c = 0; c < L; ++c) d[c] = next[c] - d[c];
}

}  // namespace tessera
