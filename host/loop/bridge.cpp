#include "loop/detail/bridge.h"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace tessera {
namespace {

// Directed edge a→b → face, for the faces still present.
using HalfEdges = std::map<std::pair<uint32_t, uint32_t>, uint32_t>;

HalfEdges halfEdgesOf(const std::vector<uint32_t>& tris, const std::vector<uint8_t>& gone) {
  HalfEdges h;
  for (uint32_t f = 0; f < tris.size() / 3; ++f)
    if (!gone[f])
      for (int i = 0; i < 3; ++i) h[{tris[3 * f + i], tris[3 * f + (i + 1) % 3]}] = f;
  return h;
}

// Splits `faces` into pieces, two faces being in one piece when they share an edge that
// `crosses(a, b)` lets through, and removes (sets `gone`) every piece but the largest.
// Returns whether anything was removed.
template <class Crosses>
bool keepLargestPiece(const std::vector<uint32_t>& faces, const std::vector<uint32_t>& tris,
                      const HalfEdges& h, Crosses crosses, std::vector<uint8_t>& gone) {
  std::map<uint32_t, uint32_t> piece;
  std::vector<uint32_t> sizes;
  for (uint32_t start : faces) {
    if (piece.count(start)) continue;
    const uint32_t id = uint32_t(sizes.size());
    sizes.push_back(0);
    std::vector<uint32_t> stack{start};
    piece[start] = id;
    while (!stack.empty()) {
      const uint32_t f = stack.back();
      stack.pop_back();
      ++sizes[id];
      for (int i = 0; i < 3; ++i) {
        const uint32_t a = tris[3 * f + i], b = tris[3 * f + (i + 1) % 3];
        if (!crosses(a, b)) continue;
        auto it = h.find({b, a});
        if (it != h.end() && !piece.count(it->second)) piece[it->second] = id, stack.push_back(it->second);
      }
    }
  }
  if (sizes.size() <= 1) return false;
  const uint32_t keep = uint32_t(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
  for (auto [f, id] : piece)
    if (id != keep) gone[f] = 1;
  return true;
}

// Faces of every piece of the mesh but the largest.
bool removeSmallPieces(const std::vector<uint32_t>& tris, std::vector<uint8_t>& gone) {
  std::vector<uint32_t> faces;
  for (uint32_t f = 0; f < tris.size() / 3; ++f)
    if (!gone[f]) faces.push_back(f);
  return keepLargestPiece(faces, tris, halfEdgesOf(tris, gone),
                          [](uint32_t, uint32_t) { return true; }, gone);
}

// At a vertex where two or more fans of faces meet (only the removal can make one), keeps the
// largest fan (faces around v joined across edges through v).
bool removePinchedFans(const std::vector<uint32_t>& tris, uint32_t vertexCount,
                       std::vector<uint8_t>& gone) {
  const HalfEdges h = halfEdgesOf(tris, gone);
  std::vector<std::vector<uint32_t>> facesOf(vertexCount);
  for (uint32_t f = 0; f < tris.size() / 3; ++f)
    if (!gone[f])
      for (int i = 0; i < 3; ++i) facesOf[tris[3 * f + i]].push_back(f);
  bool changed = false;
  for (uint32_t v = 0; v < vertexCount; ++v)
    changed |= keepLargestPiece(facesOf[v], tris, h,
                                [v](uint32_t a, uint32_t b) { return a == v || b == v; }, gone);
  return changed;
}

}  // namespace

LoopShape removeFaces(const LoopShape& mesh, const std::vector<uint8_t>& remove,
                      std::vector<uint32_t>& keptVertex, const std::string& what) {
  const auto& tris = mesh.topology.triangles;
  std::vector<uint8_t> gone = remove;
  for (int round = 0; round < 100; ++round) {
    const bool pieces = removeSmallPieces(tris, gone);
    const bool fans = removePinchedFans(tris, mesh.topology.vertexCount, gone);
    if (!pieces && !fans) break;
  }
  LoopShape out;
  out.name = mesh.name;
  keptVertex.assign(mesh.topology.vertexCount, kLoopNone);
  for (uint32_t f = 0; f < tris.size() / 3; ++f) {
    if (gone[f]) continue;
    for (int i = 0; i < 3; ++i) {
      uint32_t& k = keptVertex[tris[3 * f + i]];
      if (k == kLoopNone) k = uint32_t(out.positions.size()), out.positions.push_back(mesh.positions[tris[3 * f + i]]);
      out.topology.triangles.push_back(k);
    }
  }
  if (out.topology.triangles.empty())
    throw std::invalid_argument("join: no triangle of " + what + " is left outside the other mesh");
  out.topology.vertexCount = uint32_t(out.positions.size());
  return out;
}

std::vector<std::vector<uint32_t>> boundaryLoops(const LoopControlTopology& topology) {
  const auto& tris = topology.triangles;
  const HalfEdges h = halfEdgesOf(tris, std::vector<uint8_t>(tris.size() / 3, 0));
  std::map<uint32_t, uint32_t> next;  // boundary half-edge a→b, by a
  for (const auto& [edge, face] : h)
    if (!h.count({edge.second, edge.first})) next[edge.first] = edge.second;
  std::vector<std::vector<uint32_t>> loops;
  while (!next.empty()) {
    std::vector<uint32_t> loop{next.begin()->first};
    for (uint32_t v = next.begin()->second; v != loop.front(); v = next.at(v)) loop.push_back(v);
    for (uint32_t v : loop) next.erase(v);
    loops.push_back(std::move(loop));
  }
  return loops;
}

std::vector<uint32_t> bridgeLoops(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b,
                                  const std::vector<glm::dvec3>& p) {
  size_t ka = 0, kb = 0;
  double best = 1e300;
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t j = 0; j < b.size(); ++j) {
      const double d = glm::length(p[a[i]] - p[b[j]]);
      if (d < best) best = d, ka = i, kb = j;
    }
  // a is walked forwards, b backwards: the loops run opposite ways around the bridge.
  auto A = [&](size_t step) { return a[(ka + step) % a.size()]; };
  auto B = [&](size_t step) { return b[(kb + b.size() - step % b.size()) % b.size()]; };
  std::vector<uint32_t> tris;
  size_t i = 0, j = 0;
  while (i < a.size() || j < b.size()) {
    const bool advanceA =
        j == b.size() ||
        (i < a.size() && glm::length(p[A(i + 1)] - p[B(j)]) <= glm::length(p[A(i)] - p[B(j + 1)]));
    if (advanceA) {
      tris.insert(tris.end(), {A(i), B(j), A(i + 1)});  // uses a's edge A(i+1)→A(i)
      ++i;
    } else {
      tris.insert(tris.end(), {B(j), B(j + 1), A(i)});  // uses b's edge B(j)→B(j+1)
      ++j;
    }
  }
  return tris;
}

}  // namespace tessera
