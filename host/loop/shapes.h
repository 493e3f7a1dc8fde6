// Control meshes for Loop tests, benchmarks and demos, generated in code with fixed seeds: a
// geodesic sphere, a noisy torus, a closed "bunny-like" blob with irregular valences 3–9, an
// open grid (boundaries, two single-triangle corners), a cube with creased edges and a sphere
// with an open crease path (crease vertices and darts). All consistently oriented,
// counter-clockwise seen from outside (closed shapes have positive signed volume).
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "loop/topology.h"

namespace tessera {

struct LoopShape {
  std::string name;
  LoopControlTopology topology;
  std::vector<glm::dvec3> positions;
};

// Icosahedron with every edge cut into `frequency` parts, projected to the unit sphere:
// 20·frequency² triangles, valences 5 (the 12 icosahedron vertices) and 6.
LoopShape loopIcosphere(int frequency);
LoopShape loopTetrahedron();
// Torus (radii 1 and 0.35) of `around` × `across` quads split into two triangles each; every
// vertex moved by up to `noise` along a pseudo-random direction.
LoopShape loopTorus(int around, int across, double noise, uint32_t seed);
// A geodesic sphere (frequency as above) with pseudo-random edge flips (valences 3–9), then
// deformed into a body, a head and two ears, plus noise.
LoopShape loopBunny(int frequency, uint32_t seed);
// Open nx × ny vertex grid over [0,1]² with small bumps in z; quads split along the same
// diagonal, so (nx−1, 0) and (0, ny−1) are single-triangle corners.
LoopShape loopGrid(int nx, int ny, uint32_t seed);
// Unit cube, two triangles per side, its 12 edges creased (its vertices become corners).
LoopShape loopCreasedCube();
// loopIcosphere(frequency) with a crease along a path of `length` edges that ends inside the
// surface (crease vertices in the middle, darts at the ends), and one marked corner.
LoopShape loopCreasedSphere(int frequency, int length);

// Signed volume (positive for closed, outward-oriented meshes).
double signedVolume(const LoopShape& shape);

}  // namespace tessera
