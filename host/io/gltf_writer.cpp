// GLB output, written directly with nlohmann::json rather than through tinygltf: the
// container is a few dozen lines, and tinygltf would bring an image-loading layer we never
// use plus a second in-memory model of data we already hold (third_party/DEPENDENCIES.md).
#include "io/gltf_writer.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "io/atomic_file.h"

namespace tessera {
namespace {

// glTF 2.0 constants (§3.6.2 accessors, §3.6.1 bufferViews, §4.4 GLB).
constexpr uint32_t kGlbMagic = 0x46546C67;      // "glTF"
constexpr uint32_t kGlbVersion = 2;
constexpr uint32_t kChunkJson = 0x4E4F534A;     // "JSON"
constexpr uint32_t kChunkBin = 0x004E4942;      // "BIN\0"
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;
constexpr int kFloat = 5126;
constexpr int kTriangles = 4;
constexpr uint32_t kExactFloatIntegers = 1u << 24;  // every integer below is a float exactly

// Little-endian bytes, appended one by one so the file is the same on any host.
class LittleEndianBytes {
 public:
  void putU16(uint16_t value) {
    bytes_ += static_cast<char>(value & 0xFF);
    bytes_ += static_cast<char>(value >> 8);
  }
  void putU32(uint32_t value) {
    for (int shift = 0; shift < 32; shift += 8) bytes_ += static_cast<char>((value >> shift) & 0xFF);
  }
  void putF32(float value) {
    uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    putU32(bits);
  }
  void padTo4(char fill) {
    while (bytes_.size() % 4 != 0) bytes_ += fill;
  }
  size_t size() const { return bytes_.size(); }
  void reserve(size_t n) { bytes_.reserve(n); }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

glm::dvec3 areaWeightedFaceNormal(const TriangleMesh& mesh, size_t triangle) {
  const glm::dvec3 a(mesh.positions[mesh.indices[3 * triangle]]);
  const glm::dvec3 b(mesh.positions[mesh.indices[3 * triangle + 1]]);
  const glm::dvec3 c(mesh.positions[mesh.indices[3 * triangle + 2]]);
  return glm::cross(b - a, c - a);  // length = twice the area: area weighting for free
}

glm::vec3 normalisedOr(const glm::dvec3& n, const glm::vec3& fallback) {
  const double length = glm::length(n);
  if (!(length > 0) || !std::isfinite(length)) return fallback;
  return glm::vec3(n / length);
}

// The NORMAL accessor's data: unit vectors everywhere (see the header for zero normals).
std::vector<glm::vec3> unitNormals(const TriangleMesh& mesh) {
  const glm::vec3 kUp(0, 0, 1);
  std::vector<glm::vec3> unit(mesh.normals.size());
  std::vector<size_t> zero;
  for (size_t v = 0; v < mesh.normals.size(); ++v) {
    const glm::dvec3 n(mesh.normals[v]);
    if (n == glm::dvec3(0))
      zero.push_back(v);
    else
      unit[v] = normalisedOr(n, kUp);
  }
  if (zero.empty()) return unit;
  std::vector<glm::dvec3> sums(mesh.normals.size(), glm::dvec3(0));
  std::vector<bool> wanted(mesh.normals.size(), false);
  for (size_t v : zero) wanted[v] = true;
  for (size_t t = 0; t < mesh.triangleCount(); ++t)
    for (int corner = 0; corner < 3; ++corner) {
      const uint32_t v = mesh.indices[3 * t + corner];
      if (wanted[v]) sums[v] += areaWeightedFaceNormal(mesh, t);
    }
  for (size_t v : zero) unit[v] = normalisedOr(sums[v], kUp);
  return unit;
}

// The buffer and its views and accessors, built together: one tightly packed bufferView per
// accessor, each starting on a 4-byte boundary.
struct DocumentBuilder {
  nlohmann::json bufferViews = nlohmann::json::array();
  nlohmann::json accessors = nlohmann::json::array();
  LittleEndianBytes bin;

  size_t beginView() {
    bin.padTo4(0);
    return bin.size();
  }

  int endView(size_t offset, int target, int componentType, const char* type, size_t count) {
    bufferViews.push_back({{"buffer", 0},
                           {"byteOffset", offset},
                           {"byteLength", bin.size() - offset},
                           {"target", target}});
    accessors.push_back({{"bufferView", bufferViews.size() - 1},
                         {"componentType", componentType},
                         {"type", type},
                         {"count", count}});
    return int(accessors.size() - 1);
  }

  // glm vectors of `components` floats (VEC2, VEC3), or floats (SCALAR).
  template <typename Value>
  int addFloats(const std::vector<Value>& values, int components, const char* type) {
    const size_t offset = beginView();
    for (const Value& value : values) {
      if constexpr (std::is_same_v<Value, float>)
        bin.putF32(value);
      else
        for (int c = 0; c < components; ++c) bin.putF32(value[c]);
    }
    return endView(offset, kArrayBuffer, kFloat, type, values.size());
  }
};

// The triangles of each face in increasing face order, each face's in mesh order; without
// faces, all triangles as one group.
std::map<uint32_t, std::vector<uint32_t>> trianglesByFace(const TriangleMesh& mesh,
                                                          const std::vector<uint32_t>* faces) {
  std::map<uint32_t, std::vector<uint32_t>> groups;
  for (uint32_t t = 0; t < mesh.triangleCount(); ++t) groups[faces ? (*faces)[t] : 0].push_back(t);
  return groups;
}

nlohmann::json emptyScene() {
  return {{"asset", {{"version", "2.0"}, {"generator", "tessera"}}},
          {"scene", 0},
          {"scenes", nlohmann::json::array({nlohmann::json::object()})}};
}

void putChunkHeader(LittleEndianBytes& glb, uint32_t type, size_t length) {
  glb.putU32(uint32_t(length));
  glb.putU32(type);
}

}  // namespace

void writeGlb(std::ostream& out, const TriangleMesh& mesh,
              const std::vector<uint32_t>* triangleFace) {
  mesh.validate();
  if (triangleFace && triangleFace->size() != mesh.triangleCount())
    throw std::invalid_argument("writeGlb: " + std::to_string(triangleFace->size()) +
                                " face indices for " + std::to_string(mesh.triangleCount()) +
                                " triangles");
  nlohmann::json document = emptyScene();
  DocumentBuilder builder;

  if (mesh.triangleCount() > 0) {
    const size_t vertexCount = mesh.vertexCount();
    builder.bin.reserve(vertexCount * 36 + mesh.indices.size() * 4 + 16);
    nlohmann::json attributes;

    const int position = builder.addFloats(mesh.positions, 3, "VEC3");
    glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-lo);
    for (const glm::vec3& p : mesh.positions) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    builder.accessors[position]["min"] = {lo.x, lo.y, lo.z};
    builder.accessors[position]["max"] = {hi.x, hi.y, hi.z};
    attributes["POSITION"] = position;

    if (!mesh.normals.empty()) {
      const std::vector<glm::vec3> unit = unitNormals(mesh);
      attributes["NORMAL"] = builder.addFloats(unit, 3, "VEC3");
    }
    if (!mesh.uvs.empty())
      attributes["TEXCOORD_0"] = builder.addFloats(mesh.uvs, 2, "VEC2");
    if (!mesh.patchIds.empty()) {
      bool exact = true;
      for (uint32_t id : mesh.patchIds) exact = exact && id < kExactFloatIntegers;
      if (exact) {
        std::vector<float> ids(mesh.patchIds.begin(), mesh.patchIds.end());
        attributes["_PATCH_ID"] = builder.addFloats(ids, 1, "SCALAR");
      }
    }

    // Every index is below vertexCount; 65535 itself would be read as primitive restart.
    const bool shortIndices = vertexCount <= 65535;
    auto addIndices = [&](const std::vector<uint32_t>& triangles) {
      const size_t offset = builder.beginView();
      for (uint32_t t : triangles)
        for (int corner = 0; corner < 3; ++corner) {
          const uint32_t index = mesh.indices[3 * size_t(t) + corner];
          if (shortIndices)
            builder.bin.putU16(uint16_t(index));
          else
            builder.bin.putU32(index);
        }
      return builder.endView(offset, kElementArrayBuffer,
                             shortIndices ? kUnsignedShort : kUnsignedInt, "SCALAR",
                             3 * triangles.size());
    };
    nlohmann::json primitives = nlohmann::json::array();
    for (const auto& [face, triangles] : trianglesByFace(mesh, triangleFace)) {
      nlohmann::json primitive = {
          {"attributes", attributes}, {"indices", addIndices(triangles)}, {"mode", kTriangles}};
      if (triangleFace) primitive["extras"] = {{"face", face}};
      primitives.push_back(std::move(primitive));
    }

    document["buffers"] = {{{"byteLength", builder.bin.size()}}};
    document["bufferViews"] = std::move(builder.bufferViews);
    document["accessors"] = std::move(builder.accessors);
    document["meshes"] = {{{"primitives", std::move(primitives)}}};
    document["nodes"] = {{{"mesh", 0}}};
    document["scenes"] = {{{"nodes", {0}}}};
  }

  std::string json = document.dump();
  while (json.size() % 4 != 0) json += ' ';
  builder.bin.padTo4(0);
  const bool hasBin = builder.bin.size() > 0;
  const uint64_t total =
      12 + 8 + uint64_t(json.size()) + (hasBin ? 8 + uint64_t(builder.bin.size()) : 0);
  if (total > std::numeric_limits<uint32_t>::max())
    throw std::invalid_argument("writeGlb: the mesh needs " + std::to_string(total) +
                                " bytes, over GLB's 4 GiB limit");

  LittleEndianBytes head;
  head.putU32(kGlbMagic);
  head.putU32(kGlbVersion);
  head.putU32(uint32_t(total));
  putChunkHeader(head, kChunkJson, json.size());
  out.write(head.bytes().data(), std::streamsize(head.size()));
  out.write(json.data(), std::streamsize(json.size()));
  if (hasBin) {
    LittleEndianBytes binHead;
    putChunkHeader(binHead, kChunkBin, builder.bin.size());
    out.write(binHead.bytes().data(), std::streamsize(binHead.size()));
    out.write(builder.bin.bytes().data(), std::streamsize(builder.bin.size()));
  }
}

void writeGlbFile(const std::string& path, const TriangleMesh& mesh,
                  const std::vector<uint32_t>* triangleFace) {
  writeFileAtomically(path, [&](std::ostream& out) { writeGlb(out, mesh, triangleFace); });
}

}  // namespace tessera
