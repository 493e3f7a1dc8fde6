// OBJ and PLY output of a mesh that arrives in parts (mesh/streamed_tessellation.h), for a
// mesh larger than the memory budget. Both formats start with counts (OBJ's comment line, PLY's
// header) and OBJ keeps each attribute in a section of its own, so the parts go to anonymous
// temporary files (std::tmpfile, removed when closed), one per section, and finish() writes
// the header and copies the sections to the output: the bytes writeObj / writePly give for the
// same vertices and triangles (MeshPrecision::Float, no metadata). Memory: one part at a time.
// Disk: about the output's size again in the temporary directory until finish().
#pragma once
#include <cstdint>
#include <cstdio>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "mesh/streamed_tessellation.h"

namespace tessera {

class MeshStreamWriter {
 public:
  enum class Format { Obj, Ply };
  // `path`: the output, for messages. Throws InputError (kind Io) naming it when a temporary
  // file cannot be made.
  MeshStreamWriter(Format format, std::string path);

  // Appends the chunk's vertices and triangles (its indices continue the earlier chunks').
  void add(const MeshChunk& chunk);
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

  Format format_;
  std::string path_;
  std::vector<TempFile> sections_;  // OBJ: v, vt, vn, f; PLY: vertex records, faces
  uint64_t vertices_ = 0, triangles_ = 0;
};

}  // namespace tessera
