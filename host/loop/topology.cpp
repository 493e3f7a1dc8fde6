#include "loop/topology.h"

#include <algorithm>

namespace tessera {
namespace {

// Half-edge h = 3f + i runs from corner i of face f to corner i + 1.
inline uint32_t nextHalfEdge(uint32_t h) { return h - h % 3 + (h % 3 + 1) % 3; }
inline uint32_t prevHalfEdge(uint32_t h) { return h - h % 3 + (h % 3 + 2) % 3; }

std::string edgeName(uint32_t a, uint32_t b) {
  return "(" + std::to_string(a) + ", " + std::to_string(b) + ")";
}

void checkTriangles(const LoopControlTopology& control) {
  if (control.triangles.size() % 3 != 0)
    throw LoopTopologyError("the index count " + std::to_string(control.triangles.size()) +
                                " is not a multiple of 3",
                            kLoopNone);
  if (control.triangles.empty()) throw LoopTopologyError("the mesh has no triangles", kLoopNone);
  for (size_t f = 0; f < control.triangles.size() / 3; ++f) {
    const uint32_t* t = &control.triangles[3 * f];
    for (int i = 0; i < 3; ++i)
      if (t[i] >= control.vertexCount)
        throw LoopTopologyError("triangle " + std::to_string(f) + " uses vertex " +
                                    std::to_string(t[i]) + ", but there are only " +
                                    std::to_string(control.vertexCount) + " vertices",
                                uint32_t(f));
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      throw LoopTopologyError("triangle " + std::to_string(f) + " (" + std::to_string(t[0]) +
                                  ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) +
                                  ") repeats a vertex",
                              uint32_t(f));
  }
}

}  // namespace

const char* loopVertexRuleName(LoopVertexRule rule) {
  switch (rule) {
    case LoopVertexRule::Smooth: return "smooth";
    case LoopVertexRule::Dart: return "dart";
    case LoopVertexRule::Crease: return "crease";
    case LoopVertexRule::Corner: return "corner";
  }
  return "unknown";
}

uint32_t LoopTopology::oppositeVertex(uint32_t e, uint32_t f) const {
  const uint32_t* t = &triangles[3 * f];
  for (int i = 0; i < 3; ++i)
    if (t[i] != edgeVertices[e][0] && t[i] != edgeVertices[e][1]) return t[i];
  return kLoopNone;
}

uint32_t LoopTopology::edgeBetween(uint32_t a, uint32_t b) const {
  if (a < vertexCount && b < vertexCount)
    for (uint32_t k = ringOffsets[a]; k < ringOffsets[a + 1]; ++k)
      if (ringVertices[k] == b) return ringEdges[k];
  return kLoopNone;
}

bool LoopTopology::closed() const {
  return std::none_of(edgeFaces.begin(), edgeFaces.end(),
                      [](const auto& faces) { return faces[1] == kLoopNone; });
}

LoopTopology buildLoopTopology(const LoopControlTopology& control) {
  checkTriangles(control);
  LoopTopology t;
  t.vertexCount = control.vertexCount;
  t.boundary = control.boundary;
  t.triangles = control.triangles;
  const uint32_t halfEdgeCount = uint32_t(t.triangles.size());
  const auto tail = [&](uint32_t h) { return t.triangles[h]; };
  const auto head = [&](uint32_t h) { return t.triangles[nextHalfEdge(h)]; };

  // Outgoing half-edges of each vertex (CSR by tail).
  std::vector<uint32_t> outOffsets(t.vertexCount + 1, 0);
  for (uint32_t h = 0; h < halfEdgeCount; ++h) ++outOffsets[tail(h) + 1];
  for (uint32_t v = 0; v < t.vertexCount; ++v) {
    if (outOffsets[v + 1] == 0)
      throw LoopTopologyError("vertex " + std::to_string(v) +
                                  " is used by no triangle (isolated vertices are not supported)",
                              kLoopNone, v);
    outOffsets[v + 1] += outOffsets[v];
  }
  std::vector<uint32_t> outgoing(halfEdgeCount);
  {
    std::vector<uint32_t> fill(outOffsets.begin(), outOffsets.end() - 1);
    for (uint32_t h = 0; h < halfEdgeCount; ++h) outgoing[fill[tail(h)]++] = h;
  }

  // Twins: the half-edge b→a for each a→b. Valences are small, so a scan of b's outgoing
  // half-edges is cheaper than a hash map.
  std::vector<uint32_t> twin(halfEdgeCount, kLoopNone);
  for (uint32_t h = 0; h < halfEdgeCount; ++h) {
    const uint32_t a = tail(h), b = head(h);
    uint32_t same = kLoopNone, opposite = kLoopNone, users = 1;
    for (uint32_t k = outOffsets[a]; k < outOffsets[a + 1]; ++k)
      if (outgoing[k] != h && head(outgoing[k]) == b) same = outgoing[k], ++users;
    for (uint32_t k = outOffsets[b]; k < outOffsets[b + 1]; ++k)
      if (head(outgoing[k]) == a) opposite = outgoing[k], ++users;
    if (users > 2)
      throw LoopTopologyError("edge " + edgeName(a, b) + " is shared by " +
                                  std::to_string(users) +
                                  " triangles (non-manifold); triangle " + std::to_string(h / 3) +
                                  " is one of them",
                              h / 3);
    if (same != kLoopNone)
      throw LoopTopologyError("triangles " + std::to_string(h / 3) + " and " +
                                  std::to_string(same / 3) + " both run along edge " +
                                  edgeName(a, b) +
                                  " in the same direction: the triangles are not "
                                  "consistently oriented",
                              same / 3);
    twin[h] = opposite;
  }

  // Edges, numbered in the order of their first half-edge.
  std::vector<uint32_t> halfEdgeEdge(halfEdgeCount, kLoopNone);
  for (uint32_t h = 0; h < halfEdgeCount; ++h) {
    if (twin[h] != kLoopNone && twin[h] < h) continue;
    const uint32_t e = uint32_t(t.edgeVertices.size());
    t.edgeVertices.push_back({std::min(tail(h), head(h)), std::max(tail(h), head(h))});
    t.edgeFaces.push_back({h / 3, twin[h] == kLoopNone ? kLoopNone : twin[h] / 3});
    halfEdgeEdge[h] = e;
    if (twin[h] != kLoopNone) halfEdgeEdge[twin[h]] = e;
  }
  t.faceEdges = halfEdgeEdge;  // half-edge 3f + i is edge i of face f

  // One-rings: walk counter-clockwise from the half-edge whose clockwise neighbour is missing
  // (a boundary vertex has exactly one), or from any half-edge of an interior vertex.
  t.vertexBoundary.assign(t.vertexCount, 0);
  t.ringOffsets.assign(t.vertexCount + 1, 0);
  t.ringVertices.reserve(halfEdgeCount + t.vertexCount);
  t.ringEdges.reserve(halfEdgeCount + t.vertexCount);
  for (uint32_t v = 0; v < t.vertexCount; ++v) {
    const uint32_t begin = outOffsets[v], end = outOffsets[v + 1];
    uint32_t start = outgoing[begin], starts = 0;
    for (uint32_t k = begin; k < end; ++k)
      if (twin[outgoing[k]] == kLoopNone) start = outgoing[k], ++starts;
    uint32_t visited = 0;
    for (uint32_t h = start; visited < end - begin;) {
      t.ringVertices.push_back(head(h));
      t.ringEdges.push_back(halfEdgeEdge[h]);
      ++visited;
      const uint32_t back = prevHalfEdge(h);  // the face's half-edge into v
      if (twin[back] == kLoopNone) {
        t.ringVertices.push_back(tail(back));
        t.ringEdges.push_back(halfEdgeEdge[back]);
        t.vertexBoundary[v] = 1;
        break;
      }
      if (twin[back] == start) break;
      h = twin[back];
    }
    if (starts > 1 || visited != end - begin)
      throw LoopTopologyError("vertex " + std::to_string(v) +
                                  " is non-manifold: its triangles form more than one fan",
                              start / 3, v);
    t.ringOffsets[v + 1] = uint32_t(t.ringVertices.size());
  }

  t.edgeCrease.assign(t.edgeCount(), 0);
  for (const auto& crease : control.creases) {
    const uint32_t e = t.edgeBetween(crease[0], crease[1]);
    if (e == kLoopNone)
      throw LoopTopologyError("crease " + edgeName(crease[0], crease[1]) + " is not an edge",
                              kLoopNone);
    t.edgeCrease[e] = 1;
  }
  t.edgeSharp.resize(t.edgeCount());
  for (size_t e = 0; e < t.edgeCount(); ++e)
    t.edgeSharp[e] = t.edgeCrease[e] || t.edgeFaces[e][1] == kLoopNone;

  t.vertexMarkedCorner.assign(t.vertexCount, 0);
  for (uint32_t v : control.corners) {
    if (v >= t.vertexCount)
      throw LoopTopologyError("corner vertex " + std::to_string(v) + " does not exist",
                              kLoopNone, v);
    t.vertexMarkedCorner[v] = 1;
  }
  // An interior vertex of two triangles: they share both its edges, so they are one triangle
  // in opposite orientations (a two-sided "pillow"), whose refinement is no manifold.
  for (uint32_t v = 0; v < t.vertexCount; ++v) {
    if (t.vertexBoundary[v] || t.valence(v) != 2) continue;
    std::vector<uint32_t> faces;
    for (uint32_t f = 0; f < t.faceCount(); ++f)
      for (int c = 0; c < 3; ++c)
        if (t.triangles[3 * f + c] == v) faces.push_back(f);
    throw LoopTopologyError("triangles " + std::to_string(faces.front()) + " and " +
                                std::to_string(faces.back()) +
                                " are the same triangle in opposite orientations (a two-sided "
                                "triangle around vertex " + std::to_string(v) + ")",
                            faces.back(), v);
  }
  t.vertexRule.resize(t.vertexCount);
  for (uint32_t v = 0; v < t.vertexCount; ++v) {
    uint32_t sharp = 0;
    for (uint32_t k = t.ringOffsets[v]; k < t.ringOffsets[v + 1]; ++k)
      sharp += t.edgeSharp[t.ringEdges[k]];
    const bool singleFace = control.boundary == LoopBoundary::EdgeAndCorner &&
                            t.vertexBoundary[v] && t.faceValence(v) == 1;
    if (t.vertexMarkedCorner[v] || singleFace || sharp >= 3)
      t.vertexRule[v] = LoopVertexRule::Corner;
    else if (sharp == 2)
      t.vertexRule[v] = LoopVertexRule::Crease;
    else
      t.vertexRule[v] = sharp == 1 ? LoopVertexRule::Dart : LoopVertexRule::Smooth;
  }
  return t;
}

LoopTopology refineLoopTopology(const LoopTopology& coarse) {
  LoopControlTopology fine;
  fine.boundary = coarse.boundary;
  const uint32_t n = coarse.vertexCount;
  fine.vertexCount = n + uint32_t(coarse.edgeCount());
  fine.triangles.reserve(coarse.triangles.size() * 4);
  for (size_t f = 0; f < coarse.faceCount(); ++f) {
    const uint32_t* v = &coarse.triangles[3 * f];
    const uint32_t ab = n + coarse.faceEdges[3 * f], bc = n + coarse.faceEdges[3 * f + 1],
                   ca = n + coarse.faceEdges[3 * f + 2];
    const uint32_t children[12] = {v[0], ab, ca, ab, v[1], bc, ca, bc, v[2], ab, bc, ca};
    fine.triangles.insert(fine.triangles.end(), children, children + 12);
  }
  for (size_t e = 0; e < coarse.edgeCount(); ++e)
    if (coarse.edgeCrease[e]) {
      fine.creases.push_back({coarse.edgeVertices[e][0], n + uint32_t(e)});
      fine.creases.push_back({n + uint32_t(e), coarse.edgeVertices[e][1]});
    }
  for (uint32_t v = 0; v < n; ++v)
    if (coarse.vertexMarkedCorner[v]) fine.corners.push_back(v);
  return buildLoopTopology(fine);
}

}  // namespace tessera
