#include "io/mesh_stream_writer.h"

#include <cerrno>
#include <cstring>
#include <sstream>

#include "io/obj_writer.h"
#include "io/ply_writer.h"
#include "tessera/errors.h"

namespace tessera {

MeshStreamWriter::MeshStreamWriter(Format format, std::string path)
    : format_(format), path_(std::move(path)) {
  const size_t count = format == Format::Obj ? 4 : 2;
  for (size_t i = 0; i < count; ++i) {
    sections_.emplace_back(std::tmpfile());
    if (!sections_.back())
      throw InputError(InputErrorKind::Io, path_, 0,
                       std::string("cannot make a temporary file for streaming the mesh: ") +
                           std::strerror(errno));
  }
}

void MeshStreamWriter::append(size_t section, const std::string& bytes) {
  if (std::fwrite(bytes.data(), 1, bytes.size(), sections_[section].get()) != bytes.size())
    throw InputError(InputErrorKind::Io, path_, 0,
                     std::string("cannot write the mesh's temporary file: ") + std::strerror(errno));
}

void MeshStreamWriter::add(const MeshChunk& chunk) {
  std::ostringstream text;
  const auto flushInto = [&](size_t section) {
    append(section, text.str());
    text.str({});
  };
  if (format_ == Format::Obj) {
    writeObjVectors(text, "v", chunk.positions);
    flushInto(0);
    writeObjUvs(text, chunk.uvs);
    flushInto(1);
    writeObjVectors(text, "vn", chunk.normals);
    flushInto(2);
    writeObjFaces(text, chunk.indices, true, true);
    flushInto(3);
  } else {
    writePlyVertices(text, chunk.positions, chunk.normals);
    flushInto(0);
    writePlyFaces(text, chunk.indices);
    flushInto(1);
  }
  vertices_ += chunk.positions.size();
  triangles_ += chunk.indices.size() / 3;
}

void MeshStreamWriter::finish(std::ostream& out) {
  if (format_ == Format::Obj)
    writeObjComment(out, vertices_, triangles_);
  else
    out << plyHeader(vertices_, triangles_, {true, true, true}, {});
  std::vector<char> block(size_t(1) << 20);
  for (const TempFile& section : sections_) {
    std::FILE* f = section.get();
    if (std::fflush(f) != 0 || std::fseek(f, 0, SEEK_SET) != 0)
      throw InputError(InputErrorKind::Io, path_, 0,
                       std::string("cannot read back the mesh's temporary file: ") +
                           std::strerror(errno));
    size_t got;
    while ((got = std::fread(block.data(), 1, block.size(), f)) > 0)
      out.write(block.data(), std::streamsize(got));
    if (std::ferror(f))
      throw InputError(InputErrorKind::Io, path_, 0,
                       "cannot read back the mesh's temporary file");
  }
}

}  // namespace tessera
