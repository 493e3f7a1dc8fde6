// Binary PLY output of a TriangleMesh: compact and exact (raw fp32), read by MeshLab,
// Blender, Open3D and most geometry tools.
//
// Format: binary_little_endian 1.0 whatever the host's byte order. Header:
//   ply
//   format binary_little_endian 1.0
//   comment Tessera triangle mesh
//   element vertex <V>
//   property float x / y / z            (three lines)
//   property float nx / ny / nz         (three lines, only when the mesh has normals)
//   element face <F>
//   property list uchar uint vertex_indices
//   end_header
// then V vertices of 12 (or 24 with normals) bytes and F faces of 13 bytes (count 3, three
// uint32 indices). With MeshPrecision::Double the six vertex properties are `double` (8 bytes
// each: 24 or 48 bytes a vertex). With options.metadata, after those: `property float u`,
// `property float v` (when the mesh has uvs) and `property uint patch` (patchIds): the names
// assimp and VTK read as texture coordinates, and meshio keeps as point data (a welded
// vertex's patch is one of those that share it). Each header line ends in a single '\n'.
#pragma once
#include <ostream>
#include <cstdint>
#include <string>
#include <vector>

#include "io/mesh_write_options.h"
#include "mesh/mesh.h"

namespace tessera {

// Validate the mesh (std::invalid_argument if malformed) and write it to `out`.
void writePly(std::ostream& out, const TriangleMesh& mesh, const MeshWriteOptions& options = {});

// Same, into the file at `path` via writeFileAtomically: the whole file or, on any error,
// nothing (InputError of kind Io for I/O failures). An invalid mesh throws
// std::invalid_argument and leaves the file as it was.
void writePlyFile(const std::string& path, const TriangleMesh& mesh,
                  const MeshWriteOptions& options = {});

// writePly's parts, byte for byte, for a writer that puts a mesh out in parts
// (io/mesh_stream_writer.h): the header for the given counts and vertex properties; vertex
// records at MeshPrecision::Float without metadata (normals: empty, or one per position);
// face records.
struct PlyVertexLayout {
  bool normals = false, uvs = false, patchIds = false;
};
std::string plyHeader(uint64_t vertices, uint64_t faces, const PlyVertexLayout& layout,
                      const MeshWriteOptions& options);
void writePlyVertices(std::ostream& out, const std::vector<glm::vec3>& positions,
                      const std::vector<glm::vec3>& normals);
void writePlyFaces(std::ostream& out, const std::vector<uint32_t>& indices);

}  // namespace tessera
