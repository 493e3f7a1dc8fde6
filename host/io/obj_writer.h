// Wavefront OBJ output of a TriangleMesh, for viewing a tessellation in any mesh tool.
//
// Layout: a comment line, then "v x y z" per vertex, "vt u v" per vertex when the mesh has
// uvs, "vn x y z" per vertex when it has normals, then one "f" line per triangle with 1-based
// indices: "f a b c", "f a/a b/b c/c" (uvs), "f a//a b//b c//c" (normals) or "f a/a/a …"
// (both); every attribute shares the position's index. Floats are written as the shortest
// decimal that reads back to the same float (std::to_chars: exact round trip, independent of
// the locale); with MeshPrecision::Double, positions and normals as the shortest decimal that
// reads back to the same double (at most 17 significant digits), uvs stay fp32. OBJ has no
// per-vertex slot for patch ids, so patchIds are not written; with options.metadata a
// "g patch_<id>" line (trianglePatchIds) starts each run of triangles of one patch.
#pragma once
#include <ostream>
#include <cstdint>
#include <string>
#include <vector>

#include "io/mesh_write_options.h"
#include "mesh/mesh.h"

namespace tessera {

// Validate the mesh (std::invalid_argument if malformed) and write it to `out`.
void writeObj(std::ostream& out, const TriangleMesh& mesh, const MeshWriteOptions& options = {});

// Same, into the file at `path` via writeFileAtomically: the whole file or, on any error,
// nothing (InputError of kind Io for I/O failures). An invalid mesh throws
// std::invalid_argument and leaves the file as it was.
void writeObjFile(const std::string& path, const TriangleMesh& mesh,
                  const MeshWriteOptions& options = {});

// writeObj's sections at MeshPrecision::Float without metadata, byte for byte, for a writer
// that puts a mesh out in parts (io/mesh_stream_writer.h): the comment line, "v"/"vn" lines,
// "vt" lines, and "f" lines of `indices` (0-based here, written 1-based).
void writeObjComment(std::ostream& out, uint64_t vertices, uint64_t triangles);
void writeObjVectors(std::ostream& out, const char* tag, const std::vector<glm::vec3>& values);
void writeObjUvs(std::ostream& out, const std::vector<glm::vec2>& uvs);
void writeObjFaces(std::ostream& out, const std::vector<uint32_t>& indices, bool hasUvs,
                   bool hasNormals);

}  // namespace tessera
