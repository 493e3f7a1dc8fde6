#include "io/mesh_stream_writer.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include "io/obj_writer.h"
#include "io/ply_writer.h"
#include "tessera/errors.h"

namespace tessera {
namespace {

size_t sectionCount(MeshStreamWriter::Format format) {
  switch (format) {
    case MeshStreamWriter::Format::Obj: return 4;
    case MeshStreamWriter::Format::Ply: return 2;
    case MeshStreamWriter::Format::Glb: return 5;
  }
  return 0;
}

void checkChunk(const MeshChunk& chunk, uint64_t verticesBefore) {
  const size_t n = chunk.positions.size();
  for (size_t size : {chunk.normals.size(), chunk.uvs.size(), chunk.patchIds.size()})
    if (size != 0 && size != n)
      throw std::invalid_argument("MeshStreamWriter: a chunk with " + std::to_string(n) +
                                  " positions has an attribute of " + std::to_string(size));
  if (chunk.indices.size() % 3 != 0)
    throw std::invalid_argument("MeshStreamWriter: a chunk's index count is not a multiple of 3");
  for (uint32_t index : chunk.indices)
    if (index >= verticesBefore + n)
      throw std::invalid_argument("MeshStreamWriter: index " + std::to_string(index) +
                                  " past the " + std::to_string(verticesBefore + n) +
                                  " vertices so far");
}

// A vector of glm vectors as its floats (glm packs their components).
template <typename Vector>
const float* floats(const std::vector<Vector>& values) {
  return reinterpret_cast<const float*>(values.data());
}

float floatAt(const unsigned char* bytes) {
  const uint32_t bits = uint32_t(bytes[0]) | uint32_t(bytes[1]) << 8 | uint32_t(bytes[2]) << 16 |
                        uint32_t(bytes[3]) << 24;
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

}  // namespace

MeshStreamWriter::MeshStreamWriter(Format format, std::string path)
    : format_(format), path_(std::move(path)) {
  for (size_t i = 0; i < sectionCount(format); ++i) {
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
  checkChunk(chunk, vertices_);
  if (format_ == Format::Glb) return addGlb(chunk);
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

void MeshStreamWriter::addGlb(const MeshChunk& chunk) {
  const uint64_t first = vertices_;
  std::string bytes;
  const auto flushInto = [&](size_t section) {
    append(section, bytes);
    bytes.clear();
  };
  appendGlbFloats(bytes, floats(chunk.positions), 3 * chunk.positions.size());
  flushInto(0);
  for (const glm::vec3& p : chunk.positions) {
    min_ = glm::min(min_, p);
    max_ = glm::max(max_, p);
  }
  std::vector<glm::vec3> unit(chunk.normals.size());
  for (size_t i = 0; i < chunk.normals.size(); ++i) {
    if (isZeroNormal(chunk.normals[i]))
      zeroNormals_.push_back(uint32_t(first + i));  // its slot: 0 until finish()
    else
      unit[i] = glbUnitNormal(chunk.normals[i]);
  }
  appendGlbFloats(bytes, floats(unit), 3 * unit.size());
  flushInto(1);
  appendGlbFloats(bytes, floats(chunk.uvs), 2 * chunk.uvs.size());
  flushInto(2);
  for (uint32_t id : chunk.patchIds) {
    const float value = float(id);
    patchIdsFit_ = patchIdsFit_ && glbPatchIdFits(id);
    appendGlbFloats(bytes, &value, 1);
  }
  flushInto(3);
  appendGlbIndices(bytes, chunk.indices.data(), chunk.indices.size(), false);
  flushInto(4);
  if (!zeroNormals_.empty())
    for (size_t k = 0; k < chunk.indices.size(); k += 3) {
      const uint32_t* corners = &chunk.indices[k];
      if (std::any_of(corners, corners + 3, [&](uint32_t v) {
            return std::binary_search(zeroNormals_.begin(), zeroNormals_.end(), v);
          }))
        zeroNormalTriangles_.insert(zeroNormalTriangles_.end(), corners, corners + 3);
    }
  vertices_ += chunk.positions.size();
  triangles_ += chunk.indices.size() / 3;
  normals_ += chunk.normals.size();
  uvs_ += chunk.uvs.size();
  patchIds_ += chunk.patchIds.size();
  // Refused as soon as it cannot fit, not after the whole tessellation: the file only grows.
  checkGlbSize(28 + glbBinLength(glbLayout()));
}

GlbLayout MeshStreamWriter::glbLayout() const {
  GlbLayout layout;
  if (triangles_ == 0) return layout;  // an empty scene, as writeGlb writes it
  layout.vertices = vertices_;
  layout.normals = normals_ > 0;
  layout.uvs = uvs_ > 0;
  layout.patchIds = patchIds_ > 0 && patchIdsFit_;
  layout.min = min_;
  layout.max = max_;
  layout.primitives = {{0, 3 * triangles_}};
  return layout;
}

std::FILE* MeshStreamWriter::rewound(size_t section) {
  std::FILE* f = sections_[section].get();
  if (std::fflush(f) != 0 || std::fseek(f, 0, SEEK_SET) != 0)
    throw InputError(InputErrorKind::Io, path_, 0,
                     std::string("cannot read back the mesh's temporary file: ") +
                         std::strerror(errno));
  return f;
}

uint64_t MeshStreamWriter::copy(size_t section, std::ostream& out) {
  std::FILE* f = rewound(section);
  std::vector<char> block(size_t(1) << 20);
  uint64_t total = 0;
  size_t got;
  while ((got = std::fread(block.data(), 1, block.size(), f)) > 0) {
    out.write(block.data(), std::streamsize(got));
    total += got;
  }
  if (std::ferror(f))
    throw InputError(InputErrorKind::Io, path_, 0, "cannot read back the mesh's temporary file");
  return total;
}

uint64_t MeshStreamWriter::copyAsShortIndices(size_t section, std::ostream& out) {
  std::FILE* f = rewound(section);
  std::vector<uint32_t> indices(size_t(1) << 18);
  std::vector<unsigned char> raw(4 * indices.size());
  std::string bytes;
  uint64_t total = 0;
  size_t got;
  while ((got = std::fread(raw.data(), 4, indices.size(), f)) > 0) {
    for (size_t i = 0; i < got; ++i)
      indices[i] = uint32_t(raw[4 * i]) | uint32_t(raw[4 * i + 1]) << 8 |
                   uint32_t(raw[4 * i + 2]) << 16 | uint32_t(raw[4 * i + 3]) << 24;
    bytes.clear();
    appendGlbIndices(bytes, indices.data(), got, true);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    total += bytes.size();
  }
  if (std::ferror(f))
    throw InputError(InputErrorKind::Io, path_, 0, "cannot read back the mesh's temporary file");
  return total;
}

// writeGlb's unitNormals for the zero normals, summing the same face normals in the same
// order; the positions are read back from their section.
void MeshStreamWriter::replaceZeroNormals() {
  const auto fail = [&] {
    throw InputError(InputErrorKind::Io, path_, 0,
                     std::string("cannot read back the mesh's temporary file: ") +
                         std::strerror(errno));
  };
  std::FILE* positions = rewound(0);
  const auto position = [&](uint32_t v) {
    unsigned char bytes[12];
    if (std::fseek(positions, long(12 * uint64_t(v)), SEEK_SET) != 0 ||
        std::fread(bytes, 1, 12, positions) != 12)
      fail();
    return glm::vec3(floatAt(bytes), floatAt(bytes + 4), floatAt(bytes + 8));
  };
  std::vector<glm::dvec3> sums(zeroNormals_.size(), glm::dvec3(0));
  for (size_t k = 0; k < zeroNormalTriangles_.size(); k += 3) {
    const uint32_t* corners = &zeroNormalTriangles_[k];
    const glm::dvec3 face =
        glbFaceNormal(position(corners[0]), position(corners[1]), position(corners[2]));
    for (int c = 0; c < 3; ++c) {
      const auto at = std::lower_bound(zeroNormals_.begin(), zeroNormals_.end(), corners[c]);
      if (at != zeroNormals_.end() && *at == corners[c]) sums[size_t(at - zeroNormals_.begin())] += face;
    }
  }
  std::FILE* normals = rewound(1);
  std::string bytes;
  for (size_t z = 0; z < zeroNormals_.size(); ++z) {
    const glm::vec3 unit = glbSummedNormal(sums[z]);
    bytes.clear();
    appendGlbFloats(bytes, &unit.x, 3);
    if (std::fseek(normals, long(12 * uint64_t(zeroNormals_[z])), SEEK_SET) != 0 ||
        std::fwrite(bytes.data(), 1, bytes.size(), normals) != bytes.size())
      fail();
  }
}

void MeshStreamWriter::finishGlb(std::ostream& out) {
  for (uint64_t count : {normals_, uvs_, patchIds_})
    if (count != 0 && count != vertices_)
      throw std::invalid_argument("MeshStreamWriter: an attribute of " + std::to_string(count) +
                                  " values for " + std::to_string(vertices_) + " vertices");
  const GlbLayout layout = glbLayout();
  if (layout.normals && !zeroNormals_.empty()) replaceZeroNormals();
  const std::vector<GlbView> views = glbViews(layout);
  const uint64_t binLength = glbBinLength(layout);
  writeGlbContainer(out, glbJsonChunk(layout), binLength, [&](std::ostream& to) {
    uint64_t written = 0;
    size_t view = 0;
    const auto padTo = [&](uint64_t offset) {
      for (; written < offset; ++written) to.put(0);
    };
    const auto next = [&](size_t section) {
      padTo(views[view++].offset);
      written += section == 4 && layout.shortIndices() ? copyAsShortIndices(section, to)
                                                       : copy(section, to);
    };
    next(0);
    if (layout.normals) next(1);
    if (layout.uvs) next(2);
    if (layout.patchIds) next(3);
    next(4);
    padTo(binLength);
  });
}

void MeshStreamWriter::finish(std::ostream& out) {
  if (format_ == Format::Glb) return finishGlb(out);
  if (format_ == Format::Obj)
    writeObjComment(out, vertices_, triangles_);
  else
    out << plyHeader(vertices_, triangles_, {true, true, true}, {});
  for (size_t section = 0; section < sections_.size(); ++section) copy(section, out);
}

}  // namespace tessera
