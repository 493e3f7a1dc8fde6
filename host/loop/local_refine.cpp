#include "loop/local_refine.h"

#include <stdexcept>

#include "loop/refine.h"

namespace tessera {

LocalRefinement refineLocally(const LoopShape& mesh, const std::vector<uint8_t>& split,
                              const std::vector<uint8_t>& previous) {
  const LoopTopology t = buildLoopTopology(mesh.topology);
  if (split.size() != t.faceCount())
    throw std::invalid_argument("refineLocally: " + std::to_string(split.size()) +
                                " flags for " + std::to_string(t.faceCount()) + " faces");
  LocalRefinement out;
  out.mesh.name = mesh.name;
  out.mesh.positions = mesh.positions;
  out.refined = previous.empty() ? std::vector<uint8_t>(t.vertexCount, 0) : previous;
  out.mesh.topology.creases.clear();
  out.mesh.topology.corners = mesh.topology.corners;

  // A new vertex on every edge of a split face, placed by Loop's edge mask.
  std::vector<uint32_t> edgeVertex(t.edgeCount(), kLoopNone);
  LoopMask mask;
  for (size_t f = 0; f < t.faceCount(); ++f) {
    if (!split[f]) continue;
    for (int i = 0; i < 3; ++i) {
      const uint32_t e = t.faceEdges[3 * f + i];
      if (edgeVertex[e] != kLoopNone) continue;
      loopEdgeMask(t, e, mask);
      edgeVertex[e] = uint32_t(out.mesh.positions.size());
      out.mesh.positions.push_back(mask.apply(mesh.positions));
      out.refined.push_back(1);
    }
  }
  auto& tris = out.mesh.topology.triangles;
  auto add = [&](uint32_t a, uint32_t b, uint32_t c) { tris.insert(tris.end(), {a, b, c}); };
  const auto& p = out.mesh.positions;
  for (size_t f = 0; f < t.faceCount(); ++f) {
    const uint32_t* c = &t.triangles[3 * f];
    uint32_t m[3];  // m[i] on the edge from corner i to corner i + 1, or kLoopNone
    int count = 0;
    for (int i = 0; i < 3; ++i) count += (m[i] = edgeVertex[t.faceEdges[3 * f + i]]) != kLoopNone;
    if (count == 0) {
      add(c[0], c[1], c[2]);
    } else if (count == 3) {  // a split face, or three T-nodes: the regular split
      add(c[0], m[0], m[2]);
      add(m[0], c[1], m[1]);
      add(m[2], m[1], c[2]);
      add(m[0], m[1], m[2]);
      for (int i = 0; i < 3; ++i) out.refined[c[i]] = 1;
    } else if (count == 1) {  // one T-node: join it to the opposite corner
      int i = m[0] != kLoopNone ? 0 : (m[1] != kLoopNone ? 1 : 2);
      add(c[i], m[i], c[(i + 2) % 3]);
      add(m[i], c[(i + 1) % 3], c[(i + 2) % 3]);
    } else {  // two T-nodes on edges i and i + 1: a corner triangle and a quad cut by its
              // shorter diagonal
      int i = m[2] == kLoopNone ? 0 : (m[0] == kLoopNone ? 1 : 2);
      const uint32_t a = c[i], b = c[(i + 1) % 3], d = c[(i + 2) % 3];
      const uint32_t mab = m[i], mbd = m[(i + 1) % 3];
      add(mab, b, mbd);
      if (glm::length(p[a] - p[mbd]) <= glm::length(p[mab] - p[d])) {
        add(a, mab, mbd);
        add(a, mbd, d);
      } else {
        add(a, mab, d);
        add(mab, mbd, d);
      }
    }
  }
  out.mesh.topology.vertexCount = uint32_t(out.mesh.positions.size());
  return out;
}

}  // namespace tessera
