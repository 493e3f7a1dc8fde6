// Topology of a triangle control mesh for Loop subdivision: edges, faces on either side of each
// edge, each vertex's one-ring in order, and the rule that refines each vertex (smooth, dart,
// crease, corner; Hoppe et al. 1994, OpenSubdiv's Sdc). CPU only, like OpenSubdiv's Far: the
// stencil builder (loop_stencils.h) turns it into tables the evaluators apply.
//
// Accepted input: triangles with three distinct vertex indices, consistently oriented, every
// edge shared by one (boundary) or two triangles, every vertex a single fan (a disc or a
// half-disc), every vertex used by some triangle. Anything else throws LoopTopologyError naming
// the triangle, edge or vertex. Holes are allowed: their rims are boundaries.
#pragma once
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace tessera {

constexpr uint32_t kLoopNone = 0xffffffffu;

// Bad topology. face/vertex name the offending triangle or vertex (kLoopNone where none).
class LoopTopologyError : public std::invalid_argument {
 public:
  LoopTopologyError(const std::string& message, uint32_t face, uint32_t vertex = kLoopNone)
      : std::invalid_argument(message), face_(face), vertex_(vertex) {}
  uint32_t face() const { return face_; }
  uint32_t vertex() const { return vertex_; }

 private:
  uint32_t face_;
  uint32_t vertex_;
};

// How a vertex moves under refinement and where its limit lies. Sharp edges are boundary
// edges and crease edges; a vertex on 0 or 1 sharp edges is smooth (1: a dart, refined as
// smooth), on exactly 2 a crease vertex, on 3 or more a corner. Vertices the caller marks are
// corners too, and with LoopBoundary::EdgeAndCorner so are boundary vertices of a single
// triangle: they never move.
enum class LoopVertexRule : uint8_t { Smooth, Dart, Crease, Corner };
const char* loopVertexRuleName(LoopVertexRule rule);

// OpenSubdiv's boundary interpolation (Sdc::Options::VtxBoundaryInterpolation). Both make
// boundary edges sharp; they differ only at a boundary vertex of a single triangle:
//   EdgeOnly       (VTX_BOUNDARY_EDGE_ONLY, OpenSubdiv's default): a crease vertex like any
//                  other boundary vertex, so the surface's corner is rounded off;
//   EdgeAndCorner  (VTX_BOUNDARY_EDGE_AND_CORNER, Tessera's default): a corner, kept in place.
enum class LoopBoundary : uint8_t { EdgeOnly, EdgeAndCorner };

// Triangles, infinitely sharp crease edges and corner vertices: what the caller describes.
struct LoopControlTopology {
  uint32_t vertexCount = 0;
  std::vector<uint32_t> triangles;  // 3 per face, counter-clockwise seen from outside
  std::vector<std::array<uint32_t, 2>> creases;  // edges by their two vertices (either order)
  std::vector<uint32_t> corners;                 // vertices that stay fixed
  LoopBoundary boundary = LoopBoundary::EdgeAndCorner;
};

struct LoopTopology {
  uint32_t vertexCount = 0;
  LoopBoundary boundary = LoopBoundary::EdgeAndCorner;  // as given, inherited when refined
  std::vector<uint32_t> triangles;  // 3 per face
  // Edge e joins edgeVertices[e] (lower index first) and separates edgeFaces[e] (the second is
  // kLoopNone on a boundary). Edge i of face f, faceEdges[3f + i], joins corners i and i + 1.
  std::vector<std::array<uint32_t, 2>> edgeVertices;
  std::vector<std::array<uint32_t, 2>> edgeFaces;
  std::vector<uint32_t> faceEdges;
  std::vector<uint8_t> edgeCrease;  // 1: a crease given by the caller (inherited when refined)
  std::vector<uint8_t> edgeSharp;   // 1: crease or boundary: refined by the ½, ½ rule
  // One-ring of v: ringVertices[ringOffsets[v] .. ringOffsets[v + 1]), counter-clockwise (the
  // faces' winding) around v; ringEdges holds the edge to each neighbour. A boundary vertex's
  // ring runs from one boundary neighbour across its faces to the other, so it has one more
  // neighbour than faces.
  std::vector<uint32_t> ringOffsets;
  std::vector<uint32_t> ringVertices;
  std::vector<uint32_t> ringEdges;
  std::vector<uint8_t> vertexBoundary;
  std::vector<uint8_t> vertexMarkedCorner;  // a corner given by the caller (inherited)
  std::vector<LoopVertexRule> vertexRule;

  size_t faceCount() const { return triangles.size() / 3; }
  size_t edgeCount() const { return edgeVertices.size(); }
  uint32_t valence(uint32_t v) const { return ringOffsets[v + 1] - ringOffsets[v]; }
  uint32_t faceValence(uint32_t v) const { return valence(v) - vertexBoundary[v]; }
  const uint32_t* ring(uint32_t v) const { return ringVertices.data() + ringOffsets[v]; }
  const uint32_t* ringEdge(uint32_t v) const { return ringEdges.data() + ringOffsets[v]; }
  // The edge joining a and b, or kLoopNone.
  uint32_t edgeBetween(uint32_t a, uint32_t b) const;
  // The vertex of face f that is not on edge e (e must be an edge of f).
  uint32_t oppositeVertex(uint32_t e, uint32_t f) const;
  bool closed() const;  // no boundary edge
};

// Builds and checks the topology. Throws LoopTopologyError for anything the header above does
// not accept, and for creases or corners that name missing edges or vertices.
LoopTopology buildLoopTopology(const LoopControlTopology& control);

// One level of Loop refinement, topology only. Vertex v keeps its index (the "even" vertex);
// the new "odd" vertex on edge e is vertexCount + e. Face f (a, b, c) with edge vertices
// ab, bc, ca becomes faces 4f..4f+3: (a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca).
// Creases split into two creases; marked corners stay corners; the boundary rule is kept.
LoopTopology refineLoopTopology(const LoopTopology& coarse);

}  // namespace tessera
