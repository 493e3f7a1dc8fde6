// Measured chordal deviation of uniform N_u×N_v tessellations of a rational patch (rule A with
// given counts), and the smallest such grid that stays within a tolerance: the "true value"
// the division counts are compared with. Deviation is parametric, as in host/mesh/deviation.h and
// Filip's bound: a point of a triangle against the surface at the same mix of its corners'
// (u, v). Each cell [u_i,u_i+1]×[v_j,v_j+1] is split along its (u_i,v_j)–(u_i+1,v_j+1) diagonal
// (uniformGridMesh in view_dependent.h uses the same triangles). Weights may have any sign:
// a grid whose samples meet w = 0 (or both signs of w) has infinite deviation.
#pragma once
#include "geometry/homogeneous_net.h"

namespace tessera {

// Lattice density: every cell is sampled on an s×s lattice (its edges and corners included)
// with s = max(samplesPerCell, ceil(minSamplesPerDirection / N)) per direction.
struct DeviationSampling {
  int samplesPerCell = 8;
  int minSamplesPerDirection = 64;
};

// Largest deviation of the uniform grid. Stops early and returns a value > stopAbove as soon
// as one sample exceeds it (for searches that only need pass/fail).
double uniformGridDeviation(const HomogeneousNet& net, int nu, int nv,
                            const DeviationSampling& sampling = {},
                            double stopAbove = INFINITY);

struct TrueDivisions {
  int nu = 0, nv = 0;
  double deviation = 0;
  int evaluations = 0;  // grids measured by the search
  long long divisionNumber() const { return static_cast<long long>(nu) * nv; }
};

// The smallest N_u·N_v whose measured deviation is ≤ tolerance, searched as a staircase
// (N_u up, N_v down) over N_u ≤ 3·knownNu, N_v ≤ 3·knownNv from a grid known to pass, assuming
// the deviation does not grow when a count grows. The answer is the smallest of the staircase's
// grids and the known one that passes when re-measured with `verify`.
TrueDivisions smallestUniformGrid(const HomogeneousNet& net, double tolerance, int knownNu,
                                  int knownNv, const DeviationSampling& search = {4, 32},
                                  const DeviationSampling& verify = {});

// The largest ‖S_uu‖, ‖S_uv‖, ‖S_vv‖ found on a (samples+1)² grid of parameters (curves: uu
// only, samples+1 points); entries stay 0 where w vanishes at every sample.
struct SampledSecondDerivatives {
  double uu = 0, uv = 0, vv = 0;
};
SampledSecondDerivatives sampledSecondDerivatives(const HomogeneousNet& net, int samples);

}  // namespace tessera
