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

std::string plyHeader(const TriangleMesh& mesh, const MeshWriteOptions& options) {
  const std::string real = options.precision == MeshPrecision::Double ? "double" : "float";
  std::string header =
      "ply\n"
      "format binary_little_endian 1.0\n"
      "comment Tessera triangle mesh\n"
      "element vertex " + std::to_string(mesh.vertexCount()) + "\n";
  for (const char* name : {"x", "y", "z"}) header += "property " + real + " " + name + "\n";
  if (!mesh.normals.empty())
    for (const char* name : {"nx", "ny", "nz"}) header += "property " + real + " " + name + "\n";
  if (options.metadata && !mesh.uvs.empty()) header += "property float u\nproperty float v\n";
  if (options.metadata && !mesh.patchIds.empty()) header += "property uint patch\n";
  header += "element face " + std::to_string(mesh.triangleCount()) + "\n"
            "property list uchar uint vertex_indices\n"
            "end_header\n";
  return header;
}

}  // namespace

void writePly(std::ostream& out, const TriangleMesh& mesh, const MeshWriteOptions& options) {
  mesh.validate();
  ByteSink sink(out);
  sink.putText(plyHeader(mesh, options));
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
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    sink.putU8(3);
    for (int corner = 0; corner < 3; ++corner) sink.putU32(mesh.indices[3 * t + corner]);
  }
  sink.flush();
}

void writePlyFile(const std::string& path, const TriangleMesh& mesh,
                  const MeshWriteOptions& options) {
  writeFileAtomically(path, [&](std::ostream& out) { writePly(out, mesh, options); });
}

}  // namespace tessera
