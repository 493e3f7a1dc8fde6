// Dispatch on a Bézier patch's degrees to code compiled for them: the evaluators' loops over
// the net unroll and their rows stay in registers. The same operations in the same order
// either way (the build contracts no multiply-add, -ffp-contract=off), so the same doubles.
#pragma once
#include <type_traits>

#include "geometry/patch.h"

namespace tessera {

// f(N, M) with N and M std::integral_constant<int, degree or −1>: fixed for the CAD import's
// pieces (planes 1×1, cylinders and cones 2×1 or 1×2, spheres and tori 2×2, cubic extrusions
// 3×1 or 1×3, bicubic B-splines 3×3), −1 (the degrees at run time) for any other.
template <class F>
decltype(auto) withFixedDegrees(int n, int m, F&& f) {
  using std::integral_constant;
  switch (n * (kMaxDegree + 1) + m) {
    case 1 * (kMaxDegree + 1) + 1: return f(integral_constant<int, 1>(), integral_constant<int, 1>());
    case 2 * (kMaxDegree + 1) + 1: return f(integral_constant<int, 2>(), integral_constant<int, 1>());
    case 1 * (kMaxDegree + 1) + 2: return f(integral_constant<int, 1>(), integral_constant<int, 2>());
    case 2 * (kMaxDegree + 1) + 2: return f(integral_constant<int, 2>(), integral_constant<int, 2>());
    case 3 * (kMaxDegree + 1) + 1: return f(integral_constant<int, 3>(), integral_constant<int, 1>());
    case 1 * (kMaxDegree + 1) + 3: return f(integral_constant<int, 1>(), integral_constant<int, 3>());
    case 3 * (kMaxDegree + 1) + 3: return f(integral_constant<int, 3>(), integral_constant<int, 3>());
    default: return f(integral_constant<int, -1>(), integral_constant<int, -1>());
  }
}

}  // namespace tessera
