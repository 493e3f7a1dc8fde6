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
#include <array>
#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "mesh/mesh.h"

namespace tessera {

// A CAD model's parts placed more than once (docs/cad.md, "Assemblies"), written as glTF
// instances instead of as many copies of their triangles. The mesh given may hold every
// placement or only those; its first `vertices` and `triangles` are written (every part at its
// first place and the faces meshed in place: cad/instances.h appends the copies after them). The
// faces [faceFirst, faceFirst + faceCount) of a part make a glTF mesh of their own, drawn by a node
// at the first place and by one node per other placement, with its `matrix` (column-major,
// the rigid motion from the first place) and "extras": {"faceOffset": …}: there a primitive's
// face is its "face" + faceOffset.
struct GlbInstances {
  uint64_t vertices = 0, triangles = 0;
  struct Part {
    uint32_t faceFirst = 0, faceCount = 0;
    // Its vertices and triangles among the first `vertices` and `triangles`: one range each (a
    // part welds to nothing else; cad/instances.cpp checks it), what an engine draws again.
    uint32_t firstVertex = 0, vertexCount = 0, firstTriangle = 0, triangleCount = 0;
  };
  struct Placement {
    size_t part = 0;
    std::array<double, 16> matrix{};  // column-major, as glTF's (written as floats)
    int64_t faceOffset = 0;
  };
  std::vector<Part> parts;
  std::vector<Placement> placements;
};

// Validate the mesh (std::invalid_argument if malformed) and write it to `out` as GLB.
// With triangleFace (one entry per triangle: the B-rep face it belongs to, issue 17), the mesh
// has one primitive per face, in increasing face order, all sharing the vertex accessors, each
// with its own indices and "extras": {"face": <index>}; without it, one primitive. With
// `instances` (needs triangleFace), the parts' faces go to meshes of their own, placed by nodes.
void writeGlb(std::ostream& out, const TriangleMesh& mesh,
              const std::vector<uint32_t>* triangleFace = nullptr,
              const GlbInstances* instances = nullptr);

// Same, into the file at `path` via writeFileAtomically: the whole file or, on any error,
// nothing (InputError of kind Io for I/O failures). An invalid mesh throws
// std::invalid_argument and leaves the file as it was.
void writeGlbFile(const std::string& path, const TriangleMesh& mesh,
                  const std::vector<uint32_t>* triangleFace = nullptr,
                  const GlbInstances* instances = nullptr);

// writeGlb's pieces, for a writer that puts the mesh out in parts (io/mesh_stream_writer.h);
// writeGlb itself is made of them, so both give the same bytes for the same mesh.
//
// What the JSON chunk says about the mesh: counts, which attributes there are, the positions'
// bounds, and each primitive's index count.
struct GlbPrimitive {
  uint32_t face = 0;
  uint64_t indexCount = 0;
  size_t mesh = 0;  // 0: the model's mesh; 1 + p: instanced part p's
};
struct GlbLayout {
  uint64_t vertices = 0;
  bool normals = false, uvs = false, patchIds = false;
  glm::vec3 min{0}, max{0};  // of the positions
  bool faces = false;        // each primitive's "extras": {"face": …}
  std::vector<GlbPrimitive> primitives;  // none: no triangles, an empty scene and no buffer
  // Null: one mesh and one node (every primitive's mesh 0).
  const GlbInstances* instances = nullptr;
  // 16-bit indices (every index below 65535, the primitive-restart value), else 32-bit.
  bool shortIndices() const { return vertices <= 65535; }
};
// The BIN chunk's views in order: POSITION, NORMAL, TEXCOORD_0, _PATCH_ID (those present),
// then each primitive's indices; each starts on a 4-byte boundary.
struct GlbView {
  uint64_t offset = 0, length = 0;
};
std::vector<GlbView> glbViews(const GlbLayout& layout);
// The BIN chunk's length, padding included (0: no BIN chunk).
uint64_t glbBinLength(const GlbLayout& layout);
// The JSON chunk's content, padded with spaces to 4 bytes.
std::string glbJsonChunk(const GlbLayout& layout);
// The header, the JSON chunk and the BIN chunk's header, then `writeBin` (which writes
// exactly `binLength` bytes). A file over 4 GiB throws std::invalid_argument before anything
// is written.
void writeGlbContainer(std::ostream& out, const std::string& jsonChunk, uint64_t binLength,
                       const std::function<void(std::ostream&)>& writeBin);
// Throws std::invalid_argument when a GLB of `bytes` is over the 4 GiB the format can hold.
void checkGlbSize(uint64_t bytes);

// The values as the BIN chunk holds them (little-endian, whatever the host).
void appendGlbFloats(std::string& bytes, const float* values, size_t count);
void appendGlbIndices(std::string& bytes, const uint32_t* indices, size_t count, bool shortIndices);
// The NORMAL accessor's value for a normal that is not zero (isZeroNormal: replaced by the
// normalised sum of its triangles' glbFaceNormal, glbSummedNormal).
bool isZeroNormal(const glm::vec3& normal);
glm::vec3 glbUnitNormal(const glm::vec3& normal);
glm::dvec3 glbFaceNormal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);
glm::vec3 glbSummedNormal(const glm::dvec3& sum);
// _PATCH_ID is written only when every id is below 2^24 (a float holds it exactly).
bool glbPatchIdFits(uint32_t id);

}  // namespace tessera
