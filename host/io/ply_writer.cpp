// Binary PLY output. Values are serialised byte by byte in little-endian order rather than
// memcpy'd, so the file is the same on a big-endian host.
#include "io/ply_writer.h"

#include <cstdint>
#include <cstring>

#include "io/atomic_file.h"

namespace tessera {
namespace {

class ByteSink {
 public:
  explicit ByteSink(std::ostream& out) : out_(out) { bytes_.reserve(kFlushSize + 64); }

  void putText(const std::string& text) { bytes_ += text; }
  void putU8(uint8_t value) { bytes_ += static_cast<char>(value); }

  void putU32(uint32_t value) {
    for (int shift = 0; shift < 32; shift += 8) bytes_ += static_cast<char>((value >> shift) & 0xFF);
    if (bytes_.size() >= kFlushSize) flush();
  }

  void putF32(float value) {
    uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    putU32(bits);
  }

  void putF64(double value) {
    uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    putU32(uint32_t(bits));
    putU32(uint32_t(bits >> 32));
  }

  void flush() {
    out_.write(bytes_.data(), static_cast<std::streamsize>(bytes_.size()));
    bytes_.clear();
  }

 private:
  static constexpr size_t kFlushSize = 1 << 20;
  std::ostream& out_;
  std::string bytes_;
};

}  // namespace

std::string plyHeader(uint64_t vertices, uint64_t faces, const PlyVertexLayout& layout,
                      const MeshWriteOptions& options) {
  const std::string real = options.precision == MeshPrecision::Double ? "double" : "float";
  std::string header =
      "ply\n"
      "format binary_little_endian 1.0\n"
      "comment Tessera triangle mesh\n"
      "element vertex " + std::to_string(vertices) + "\n";
  for (const char* name : {"x", "y", "z"}) header += "property " + real + " " + name + "\n";
  if (layout.normals)
    for (const char* name : {"nx", "ny", "nz"}) header += "property " + real + " " + name + "\n";
  if (options.metadata && layout.uvs) header += "property float u\nproperty float v\n";
  if (options.metadata && layout.patchIds) header += "property uint patch\n";
  header += "element face " + std::to_string(faces) + "\n"
            "property list uchar uint vertex_indices\n"
            "end_header\n";
  return header;
}

void writePlyVertices(std::ostream& out, const std::vector<glm::vec3>& positions,
                      const std::vector<glm::vec3>& normals) {
  ByteSink sink(out);
  for (size_t v = 0; v < positions.size(); ++v) {
    for (int c = 0; c < 3; ++c) sink.putF32(positions[v][c]);
    if (!normals.empty())
      for (int c = 0; c < 3; ++c) sink.putF32(normals[v][c]);
  }
  sink.flush();
}

void writePlyFaces(std::ostream& out, const std::vector<uint32_t>& indices) {
  ByteSink sink(out);
  for (size_t k = 0; k + 2 < indices.size(); k += 3) {
    sink.putU8(3);
    for (int corner = 0; corner < 3; ++corner) sink.putU32(indices[k + corner]);
  }
  sink.flush();
}

void writePly(std::ostream& out, const TriangleMesh& mesh, const MeshWriteOptions& options) {
  mesh.validate();
  ByteSink sink(out);
  sink.putText(plyHeader(mesh.vertexCount(), mesh.triangleCount(),
                         {!mesh.normals.empty(), !mesh.uvs.empty(), !mesh.patchIds.empty()},
                         options));
  const bool hasNormals = !mesh.normals.empty();
  const bool inDouble = options.precision == MeshPrecision::Double;
  // The double copy where the mesh has one, else the fp32 value widened.
  const auto putVector = [&](const std::vector<glm::vec3>& floats,
                             const std::vector<glm::dvec3>& doubles, size_t v) {
    for (int c = 0; c < 3; ++c) {
      if (!inDouble)
        sink.putF32(floats[v][c]);
      else
        sink.putF64(doubles.empty() ? double(floats[v][c]) : doubles[v][c]);
    }
  };
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    putVector(mesh.positions, mesh.positionsDouble, v);
    if (hasNormals) putVector(mesh.normals, mesh.normalsDouble, v);
    if (options.metadata && !mesh.uvs.empty()) {
      sink.putF32(mesh.uvs[v].x);
      sink.putF32(mesh.uvs[v].y);
    }
    if (options.metadata && !mesh.patchIds.empty()) sink.putU32(mesh.patchIds[v]);
  }
  sink.flush();
  writePlyFaces(out, mesh.indices);
}

void writePlyFile(const std::string& path, const TriangleMesh& mesh,
                  const MeshWriteOptions& options) {
  writeFileAtomically(path, [&](std::ostream& out) { writePly(out, mesh, options); });
}

}  // namespace tessera
