// Reader for Wavefront OBJ polygon meshes (positions and faces only), for meshes given to
// Tessera as input rather than produced by it.
//
//   v x y z [w]         a position; an optional 4th number (the weight w) or 3 more (the
//   v x y z r g b       common vertex-colour extension) must be numbers and are ignored
//   f a b c ...         a face of ≥ 3 corners, each "a", "a/t", "a//n" or "a/t/n" (one form
//                       per face); indices are 1-based, negative ones count back from the
//                       latest "v" (−1 is the last so far), as in the OBJ specification
//   vt, vn              counted (face corners' t and n indices are checked against them)
//   vp g o s usemtl mtllib l p mg lod bevel c_interp d_interp shadow_obj trace_obj maplib
//   usemap              ignored
//
// Strictness, as in the .bpt reader: every coordinate is a number (Syntax), finite
// (NonFinite) with |value| ≤ 1e15 (Range), parsed independently of the locale; an index of 0
// or outside the vertices (Topology; positive indices may refer to vertices defined later in
// the file, so they are checked at the end, naming the face's line); a face with fewer than 3
// corners (Topology); an unknown statement (Syntax; free-form curves and surfaces are named as
// unsupported); a file without vertices or without faces (Count). Lines starting with '#' are
// comments, and a token starting with '#' ends the statement (a trailing comment); a '\' line
// continuation is not supported. Line ends may be LF or CRLF.
// Errors are InputError (host/io/errors.h) whose what() reads "<file>:<line>: <reason>".
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <istream>
#include <string>
#include <vector>

namespace tessera {

struct PolygonMesh {
  std::vector<glm::dvec3> positions;
  // Corners of each face as 0-based indices into positions, in the file's order.
  std::vector<std::vector<uint32_t>> faces;
  // The 1-based line of each face in its file, for messages; may be empty for a mesh built in
  // code (messages then name the face by number only).
  std::vector<int> faceLines;
  // The 1-based line of each "v" record, likewise (may be empty).
  std::vector<int> vertexLines;
};

// Read the file at `path`; an unreadable file is an InputError of kind Io.
PolygonMesh readObj(const std::string& path);

// Parse OBJ text from `in`; `nameForMessages` stands for the file in error messages.
PolygonMesh parseObj(std::istream& in, const std::string& nameForMessages);

// Topology error naming the first face that is not a triangle and its line.
void validateTriangles(const PolygonMesh& mesh, const std::string& nameForMessages);

// Topology error naming the first vertex that no face uses, 1-based as in the file, and its
// "v" line: a Loop control mesh cannot take isolated vertices.
void validateNoIsolatedVertices(const PolygonMesh& mesh, const std::string& nameForMessages);

// Topology error unless the faces form an oriented 2-manifold with boundary: no face uses a
// vertex twice, no edge is shared by more than two faces (the message names the edge's
// vertices, 1-based as in the file), and two faces sharing an edge run it in opposite
// directions (consistent orientation; the message names both faces' lines), and the faces
// around each vertex form one fan joined by edges (two fans touching only at the vertex, a
// "bow tie", make the surface touch itself: the message names the vertex and a face of each
// fan). No two faces have the same corners: the same triangle twice, in opposite orientations,
// passes every check above (a closed "pillow" of two faces) but is no surface that Loop
// refinement can take (the message names both faces' lines). Holes — edges of only one face —
// are allowed. Not checked: faces that intersect geometrically.
void validateManifold(const PolygonMesh& mesh, const std::string& nameForMessages);

}  // namespace tessera
