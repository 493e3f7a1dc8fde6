// Random rational nets for the division-count tests: weights positive, with zeros, with
// negative ones, or all negative with zeros (fixed seeds in the callers).
#pragma once
#include <random>
#include <vector>

#include "geometry/homogeneous_net.h"

namespace tessera::test {

enum class WeightKind { Positive, Zeros, Negative, AllNegativeWithZeros };

// Corner weights stay non-zero (a zero corner weight sends the surface to infinity there).
// Zeros: interior weights zero with probability 0.4 (at least one). Negative: one or two
// interior weights in [−0.6, 0) (w usually stays positive on the patch; when it does not the
// method must say so).
std::vector<double> randomWeights(int n, int m, WeightKind kind, std::mt19937& rng);

// Coordinates in [−1, 1]³; a zero weight keeps a finite numerator (a point at infinity).
HomogeneousNet randomNet(int n, int m, WeightKind kind, std::mt19937& rng);

// A random cell [u0, u0+h]×[v0, v0+k] (sides 0.02..0.5) of a random patch: bidegree
// (1..3, 1..3) and weight kind chosen from `trial` in turn. `cell` is the patch's net
// restricted to it.
struct RandomCell {
  HomogeneousNet patch, cell;
  double u0 = 0, v0 = 0, h = 1, k = 1;
};
RandomCell randomCell(int trial, std::mt19937& rng);

bool hasZeroWeight(const HomogeneousNet& net);
bool hasNegativeWeight(const HomogeneousNet& net);

}  // namespace tessera::test
