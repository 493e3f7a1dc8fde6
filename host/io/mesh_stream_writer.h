// OBJ, PLY and GLB output of a mesh that arrives in parts (mesh/streamed_tessellation.h), for
// a mesh larger than the memory budget. Every format starts with counts (OBJ's comment line,
// PLY's header, GLB's JSON chunk, which also holds the positions' bounds) and OBJ and GLB keep
// each attribute in a section of its own, so the parts go to anonymous temporary files
// (std::tmpfile, removed when closed), one per section, and finish() writes the header and
// copies the sections to the output: the bytes writeObj / writePly / writeGlb give for the
// same vertices and triangles (MeshPrecision::Float, no metadata, no faces). Memory: one part
// at a time, plus for GLB the zero normals and their triangles (a zero normal becomes its
// triangles' normalised sum, io/gltf_writer.h, and a later part may add to it; they are the
// few vertices where a patch collapses), and a conversion of 32-bit indices to 16-bit at
// finish() when the mesh has at most 65535 vertices. Disk: about the output's size again in
// the temporary directory until finish().
#pragma once
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "io/gltf_writer.h"
#include "mesh/streamed_tessellation.h"

namespace tessera {

class MeshStreamWriter {
 public:
  enum class Format { Obj, Ply, Glb };
  // `path`: the output, for messages. Throws InputError (kind Io) naming it when a temporary
  // file cannot be made.
  MeshStreamWriter(Format format, std::string path);

  // Appends the chunk's vertices and triangles (its indices continue the earlier chunks').
  void add(const MeshChunk& chunk);
  // Throws std::invalid_argument for a malformed chunk (an index past the vertices so far, an
  // attribute of another count than the positions) and, for GLB, as soon as the file would
  // pass GLB's 4 GiB.
  // The whole file: header, then the sections in order. Throws InputError (kind Io) when a
  // temporary file cannot be read back.
  void finish(std::ostream& out);

  uint64_t vertices() const { return vertices_; }
  uint64_t triangles() const { return triangles_; }

 private:
  struct CloseFile {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  using TempFile = std::unique_ptr<std::FILE, CloseFile>;
  void append(size_t section, const std::string& bytes);
  std::FILE* rewound(size_t section);
  uint64_t copy(size_t section, std::ostream& out);
  uint64_t copyAsShortIndices(size_t section, std::ostream& out);
  void addGlb(const MeshChunk& chunk);
  GlbLayout glbLayout() const;
  void replaceZeroNormals();
  void finishGlb(std::ostream& out);

  Format format_;
  std::string path_;
  // OBJ: v, vt, vn, f; PLY: vertex records, faces; GLB: positions, unit normals, uvs, patch
  // ids (as floats), indices (32-bit)
  std::vector<TempFile> sections_;
  uint64_t vertices_ = 0, triangles_ = 0;
  // GLB: what the JSON chunk needs, and the zero normals (increasing) with the triangles that
  // use them (three indices each, in mesh order); their slots hold 0 until finish().
  uint64_t normals_ = 0, uvs_ = 0, patchIds_ = 0;
  bool patchIdsFit_ = true;
  glm::vec3 min_{std::numeric_limits<float>::infinity()}, max_{-min_};
  std::vector<uint32_t> zeroNormals_, zeroNormalTriangles_;
};

}  // namespace tessera
