// Test inputs for general patches (degree 1..7, rational): random patches of a given degree
// with fixed seeds, and closed surfaces of rational biquadratic patches (a torus and a sphere,
// as surfaces of revolution: The NURBS Book §8.5) whose shared boundaries are bit-identical.
#pragma once
#include <cstdint>
#include <vector>

#include "geometry/patch.h"

namespace tessera::test {

// `count` random patches of degree n×m: a wavy grid over [0,1]² with random heights, scaled
// and offset as randomBicubicPatches. With `rational`, weights uniform in [0.5, 2], and with
// `innerZero` one inner weight of each patch (there must be one: n, m ≥ 2) set to 0.
std::vector<BezierPatch> randomGeneralPatches(size_t count, int n, int m, bool rational,
                                              bool innerZero, uint32_t seed);

// A torus around the z axis: 16 rational biquadratic patches, exact.
std::vector<BezierPatch> rationalTorus(double major, double minor);

// A sphere about the origin: 8 rational biquadratic patches, exact; the sides at the poles
// are collapsed to a point.
std::vector<BezierPatch> rationalSphere(double radius);

// A quarter of the cylinder x² + y² = radius², 0 ≤ z ≤ height: one rational patch of degree
// 2×1 (data/scene_rational.json's first surface).
BezierPatch rationalQuarterCylinder(double radius, double height);

}  // namespace tessera::test
