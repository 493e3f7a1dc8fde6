// glTF 2.0 binary (.glb) output of a TriangleMesh: one file that three.js, Blender, the
// Khronos sample viewer and every game engine open directly.
//
// Container (glTF 2.0 §4.4, all little-endian whatever the host's byte order):
//   header  "glTF", version 2, total length                       12 bytes
//   JSON    chunk length, "JSON", the document, padded with ' '   to 4 bytes
//   BIN     chunk length, "BIN\0", the buffer, padded with 0      to 4 bytes
// The document holds one buffer (the BIN chunk), one bufferView per attribute and one for
// the indices (each starting on a 4-byte boundary, tightly packed, so no byteStride), one
// accessor per bufferView, one mesh with one TRIANGLES primitive (one per face, below), one node and one scene;
// asset.generator is "tessera". Vertex views have target ARRAY_BUFFER (34962), the index
// view ELEMENT_ARRAY_BUFFER (34963). No material: viewers use the spec's default.
//
// Attributes:
//   POSITION    FLOAT VEC3, the positions bit for bit; min and max as the spec requires.
//   NORMAL      FLOAT VEC3, when the mesh has normals. The spec requires unit length, so each
//               normal is normalised (in double, then rounded once). A zero normal (our
//               "no normal" at a point where the patch collapses to a curve or a point,
//               docs/conventions.md) has no direction to normalise; it is replaced by the
//               normalised sum of the vertex's triangles' face normals (area-weighted, the
//               usual smooth-shading normal), or by +Z when those cancel too.
//   TEXCOORD_0  FLOAT VEC2, when the mesh has uvs: the patch parameter (u, v) unchanged (no
//               flip of v; it is a surface parameter, not an image coordinate).
//   _PATCH_ID   FLOAT SCALAR, when the mesh has patchIds: the source patch, an
//               application-specific attribute (glTF allows integer attributes only as
//               normalised bytes/shorts, and floats hold every id below 2^24 exactly; a mesh
//               with a larger id is written without this attribute).
// Indices are UNSIGNED_SHORT when every vertex index fits below 65535 (the primitive-restart
// value the spec forbids), UNSIGNED_INT otherwise.
//
// A mesh without triangles is written as a valid file with an empty scene and no buffer
// (glTF forbids empty accessors). A file over 4 GiB (the GLB length field is 32-bit) throws
// std::invalid_argument before anything is written.
#pragma once
#include <ostream>
#include <string>
#include <vector>

#include "mesh/mesh.h"

namespace tessera {

// Validate the mesh (std::invalid_argument if malformed) and write it to `out` as GLB.
// With triangleFace (one entry per triangle: the B-rep face it belongs to, issue 17), the mesh
// has one primitive per face, in increasing face order, all sharing the vertex accessors, each
// with its own indices and "extras": {"face": <index>}; without it, one primitive.
void writeGlb(std::ostream& out, const TriangleMesh& mesh,
              const std::vector<uint32_t>* triangleFace = nullptr);

// Same, into the file at `path` via writeFileAtomically: the whole file or, on any error,
// nothing (InputError of kind Io for I/O failures). An invalid mesh throws
// std::invalid_argument and leaves the file as it was.
void writeGlbFile(const std::string& path, const TriangleMesh& mesh,
                  const std::vector<uint32_t>* triangleFace = nullptr);

}  // namespace tessera
