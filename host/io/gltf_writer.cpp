// GLB output, written directly with nlohmann::json rather than through tinygltf: the
// container is a few dozen lines, and tinygltf would bring an image-loading layer we never
// use plus a second in-memory model of data we already hold (third_party/DEPENDENCIES.md).
#include "io/gltf_writer.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>
#include <map>
#include <stdexcept>
#include <type_traits>
#include <utility>
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

void putU32(std::string& bytes, uint32_t value) {
  for (int shift = 0; shift < 32; shift += 8) bytes += static_cast<char>((value >> shift) & 0xFF);
}

void padTo4(std::string& bytes, char fill) {
  while (bytes.size() % 4 != 0) bytes += fill;
}

uint64_t roundUpTo4(uint64_t n) { return (n + 3) / 4 * 4; }

const glm::vec3 kUp(0, 0, 1);

glm::vec3 normalisedOr(const glm::dvec3& n, const glm::vec3& fallback) {
  const double length = glm::length(n);
  if (!(length > 0) || !std::isfinite(length)) return fallback;
  return glm::vec3(n / length);
}

// The NORMAL accessor's data: unit vectors everywhere (see the header for zero normals).
std::vector<glm::vec3> unitNormals(const TriangleMesh& mesh) {
  std::vector<glm::vec3> unit(mesh.normals.size());
  std::vector<size_t> zero;
  for (size_t v = 0; v < mesh.normals.size(); ++v) {
    if (isZeroNormal(mesh.normals[v]))
      zero.push_back(v);
    else
      unit[v] = glbUnitNormal(mesh.normals[v]);
  }
  if (zero.empty()) return unit;
  std::vector<glm::dvec3> sums(mesh.normals.size(), glm::dvec3(0));
  std::vector<bool> wanted(mesh.normals.size(), false);
  for (size_t v : zero) wanted[v] = true;
  const auto at = [&](size_t k) { return mesh.positions[mesh.indices[k]]; };
  for (size_t t = 0; t < mesh.triangleCount(); ++t)
    for (int corner = 0; corner < 3; ++corner) {
      const uint32_t v = mesh.indices[3 * t + corner];
      if (wanted[v]) sums[v] += glbFaceNormal(at(3 * t), at(3 * t + 1), at(3 * t + 2));
    }
  for (size_t v : zero) unit[v] = glbSummedNormal(sums[v]);
  return unit;
}

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

template <typename Value>
void appendValues(std::string& bytes, const std::vector<Value>& values) {
  static_assert(sizeof(Value) % sizeof(float) == 0, "float components");
  appendGlbFloats(bytes, reinterpret_cast<const float*>(values.data()),
                  values.size() * (sizeof(Value) / sizeof(float)));
}

}  // namespace

bool isZeroNormal(const glm::vec3& normal) { return glm::dvec3(normal) == glm::dvec3(0); }

glm::vec3 glbUnitNormal(const glm::vec3& normal) { return normalisedOr(glm::dvec3(normal), kUp); }

glm::dvec3 glbFaceNormal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::dvec3 da(a), db(b), dc(c);
  return glm::cross(db - da, dc - da);  // length = twice the area: area weighting for free
}

glm::vec3 glbSummedNormal(const glm::dvec3& sum) { return normalisedOr(sum, kUp); }

bool glbPatchIdFits(uint32_t id) { return id < kExactFloatIntegers; }

void appendGlbFloats(std::string& bytes, const float* values, size_t count) {
  for (size_t i = 0; i < count; ++i) {
    uint32_t bits;
    std::memcpy(&bits, &values[i], sizeof bits);
    putU32(bytes, bits);
  }
}

void appendGlbIndices(std::string& bytes, const uint32_t* indices, size_t count,
                      bool shortIndices) {
  for (size_t i = 0; i < count; ++i)
    if (shortIndices) {
      bytes += static_cast<char>(indices[i] & 0xFF);
      bytes += static_cast<char>((indices[i] >> 8) & 0xFF);
    } else {
      putU32(bytes, indices[i]);
    }
}

std::vector<GlbView> glbViews(const GlbLayout& layout) {
  std::vector<GlbView> views;
  if (layout.primitives.empty()) return views;
  uint64_t offset = 0;
  const auto add = [&](uint64_t length) {
    offset = roundUpTo4(offset);
    views.push_back({offset, length});
    offset += length;
  };
  add(12 * layout.vertices);
  if (layout.normals) add(12 * layout.vertices);
  if (layout.uvs) add(8 * layout.vertices);
  if (layout.patchIds) add(4 * layout.vertices);
  for (const GlbPrimitive& p : layout.primitives)
    add((layout.shortIndices() ? 2 : 4) * p.indexCount);
  return views;
}

uint64_t glbBinLength(const GlbLayout& layout) {
  const std::vector<GlbView> views = glbViews(layout);
  return views.empty() ? 0 : roundUpTo4(views.back().offset + views.back().length);
}

namespace {

// A placement's matrix as the file holds it: floats, as glTF's other numbers.
std::array<float, 16> asFloats(const std::array<double, 16>& matrix) {
  std::array<float, 16> out{};
  for (size_t k = 0; k < 16; ++k) out[k] = float(matrix[k]);
  return out;
}

// The meshes that have primitives (glTF forbids an empty one), a node drawing each where the
// mesh holds it, and a node per other placement of a part.
void placeInstances(nlohmann::json& document, std::vector<nlohmann::json> primitives,
                    const GlbInstances& instances) {
  nlohmann::json meshes = nlohmann::json::array(), nodes = nlohmann::json::array();
  std::vector<int> meshIndex(primitives.size(), -1);
  for (size_t m = 0; m < primitives.size(); ++m) {
    if (primitives[m].empty()) continue;
    meshIndex[m] = int(meshes.size());
    meshes.push_back({{"primitives", std::move(primitives[m])}});
    nodes.push_back({{"mesh", meshIndex[m]}});
  }
  for (const GlbInstances::Placement& placed : instances.placements) {
    if (meshIndex[1 + placed.part] < 0) continue;  // a part whose faces all failed
    nodes.push_back({{"mesh", meshIndex[1 + placed.part]},
                     {"matrix", asFloats(placed.matrix)},
                     {"extras", {{"faceOffset", placed.faceOffset}}}});
  }
  nlohmann::json scene = nlohmann::json::array();
  for (size_t n = 0; n < nodes.size(); ++n) scene.push_back(n);
  document["meshes"] = std::move(meshes);
  document["nodes"] = std::move(nodes);
  document["scenes"] = {{{"nodes", std::move(scene)}}};
}

// The first `vertices` and `triangles` of `mesh` (the parts at their first places and the
// faces meshed in place), with their faces.
TriangleMesh meshPrefix(const TriangleMesh& mesh, const std::vector<uint32_t>& triangleFace,
                        const GlbInstances& instances, std::vector<uint32_t>& prefixFaces) {
  if (instances.vertices > mesh.vertexCount() || instances.triangles > mesh.triangleCount())
    throw std::invalid_argument("writeGlb: instances past the mesh's end");
  const auto first = [](const auto& values, uint64_t count) {
    using Vector = std::decay_t<decltype(values)>;
    return values.empty() ? Vector() : Vector(values.begin(), values.begin() + ptrdiff_t(count));
  };
  TriangleMesh prefix;
  prefix.positions = first(mesh.positions, instances.vertices);
  prefix.normals = first(mesh.normals, instances.vertices);
  prefix.uvs = first(mesh.uvs, instances.vertices);
  prefix.patchIds = first(mesh.patchIds, instances.vertices);
  prefix.indices = first(mesh.indices, 3 * instances.triangles);
  prefix.trianglePatchIds = first(mesh.trianglePatchIds, instances.triangles);
  prefixFaces = first(triangleFace, instances.triangles);
  return prefix;
}

// The mesh a face's primitive goes to: 1 + the part holding it, or 0. The parts by their first
// face, searched (a board's thousands of parts times its faces, one by one, was quadratic).
class MeshOfFace {
 public:
  explicit MeshOfFace(const GlbInstances* instances) : instances_(instances) {
    if (!instances) return;
    for (size_t p = 0; p < instances->parts.size(); ++p)
      byFirstFace_.push_back({instances->parts[p].faceFirst, p});
    std::sort(byFirstFace_.begin(), byFirstFace_.end());
  }
  size_t operator()(uint32_t face) const {
    const auto after = std::upper_bound(byFirstFace_.begin(), byFirstFace_.end(),
                                        std::make_pair(face, std::numeric_limits<size_t>::max()));
    if (after == byFirstFace_.begin()) return 0;
    const size_t part = std::prev(after)->second;
    const GlbInstances::Part& p = instances_->parts[part];
    return face - p.faceFirst < p.faceCount ? 1 + part : 0;
  }

 private:
  const GlbInstances* instances_;
  std::vector<std::pair<uint32_t, size_t>> byFirstFace_;
};

}  // namespace

std::string glbJsonChunk(const GlbLayout& layout) {
  nlohmann::json document = emptyScene();
  const std::vector<GlbView> views = glbViews(layout);
  if (!views.empty()) {
    nlohmann::json bufferViews = nlohmann::json::array(), accessors = nlohmann::json::array();
    const auto add = [&](int target, int componentType, const char* type, uint64_t count) {
      const GlbView& view = views[bufferViews.size()];
      bufferViews.push_back({{"buffer", 0},
                             {"byteOffset", view.offset},
                             {"byteLength", view.length},
                             {"target", target}});
      accessors.push_back({{"bufferView", bufferViews.size() - 1},
                           {"componentType", componentType},
                           {"type", type},
                           {"count", count}});
      return int(accessors.size() - 1);
    };
    nlohmann::json attributes;
    const int position = add(kArrayBuffer, kFloat, "VEC3", layout.vertices);
    accessors[position]["min"] = {layout.min.x, layout.min.y, layout.min.z};
    accessors[position]["max"] = {layout.max.x, layout.max.y, layout.max.z};
    attributes["POSITION"] = position;
    if (layout.normals) attributes["NORMAL"] = add(kArrayBuffer, kFloat, "VEC3", layout.vertices);
    if (layout.uvs) attributes["TEXCOORD_0"] = add(kArrayBuffer, kFloat, "VEC2", layout.vertices);
    if (layout.patchIds)
      attributes["_PATCH_ID"] = add(kArrayBuffer, kFloat, "SCALAR", layout.vertices);
    // Per mesh (0: the model's, 1 + p: part p's), its primitives.
    const size_t meshCount = 1 + (layout.instances ? layout.instances->parts.size() : 0);
    std::vector<nlohmann::json> primitives(meshCount, nlohmann::json::array());
    for (const GlbPrimitive& p : layout.primitives) {
      const int indices = add(kElementArrayBuffer,
                              layout.shortIndices() ? kUnsignedShort : kUnsignedInt, "SCALAR",
                              p.indexCount);
      nlohmann::json primitive = {
          {"attributes", attributes}, {"indices", indices}, {"mode", kTriangles}};
      if (layout.faces) primitive["extras"] = {{"face", p.face}};
      primitives[p.mesh].push_back(std::move(primitive));
    }
    // The buffer ends with the last view; the BIN chunk pads it to 4 bytes.
    document["buffers"] = {{{"byteLength", views.back().offset + views.back().length}}};
    document["bufferViews"] = std::move(bufferViews);
    document["accessors"] = std::move(accessors);
    if (!layout.instances) {
      document["meshes"] = {{{"primitives", std::move(primitives[0])}}};
      document["nodes"] = {{{"mesh", 0}}};
      document["scenes"] = {{{"nodes", {0}}}};
    } else {
      placeInstances(document, std::move(primitives), *layout.instances);
    }
  }
  std::string json = document.dump();
  padTo4(json, ' ');
  return json;
}

void checkGlbSize(uint64_t bytes) {
  if (bytes > std::numeric_limits<uint32_t>::max())
    throw std::invalid_argument("writeGlb: the mesh needs " + std::to_string(bytes) +
                                " bytes, over GLB's 4 GiB limit");
}

void writeGlbContainer(std::ostream& out, const std::string& jsonChunk, uint64_t binLength,
                       const std::function<void(std::ostream&)>& writeBin) {
  const uint64_t total = 12 + 8 + uint64_t(jsonChunk.size()) + (binLength ? 8 + binLength : 0);
  checkGlbSize(total);
  std::string head;
  putU32(head, kGlbMagic);
  putU32(head, kGlbVersion);
  putU32(head, uint32_t(total));
  putU32(head, uint32_t(jsonChunk.size()));
  putU32(head, kChunkJson);
  out.write(head.data(), std::streamsize(head.size()));
  out.write(jsonChunk.data(), std::streamsize(jsonChunk.size()));
  if (binLength) {
    std::string binHead;
    putU32(binHead, uint32_t(binLength));
    putU32(binHead, kChunkBin);
    out.write(binHead.data(), std::streamsize(binHead.size()));
    writeBin(out);
  }
}

void writeGlb(std::ostream& out, const TriangleMesh& fullMesh,
              const std::vector<uint32_t>* triangleFace, const GlbInstances* instances) {
  fullMesh.validate();
  if (triangleFace && triangleFace->size() != fullMesh.triangleCount())
    throw std::invalid_argument("writeGlb: " + std::to_string(triangleFace->size()) +
                                " face indices for " + std::to_string(fullMesh.triangleCount()) +
                                " triangles");
  if (instances && !triangleFace)
    throw std::invalid_argument("writeGlb: instances without the triangles' faces");
  if (instances)
    for (const GlbInstances::Placement& placed : instances->placements)
      if (placed.part >= instances->parts.size())
        throw std::invalid_argument("writeGlb: a placement of part " + std::to_string(placed.part) +
                                    " of " + std::to_string(instances->parts.size()));
  // With instances, the placements' copies are left out: their parts' nodes draw them.
  std::vector<uint32_t> prefixFaces;
  const TriangleMesh prefix =
      instances ? meshPrefix(fullMesh, *triangleFace, *instances, prefixFaces) : TriangleMesh();
  if (instances) {
    prefix.validate();  // the copies' vertices are after the prefix's, never under it
    triangleFace = &prefixFaces;
  }
  const TriangleMesh& mesh = instances ? prefix : fullMesh;
  GlbLayout layout;
  std::string bin;
  if (mesh.triangleCount() > 0) {
    layout.vertices = mesh.vertexCount();
    layout.normals = !mesh.normals.empty();
    layout.uvs = !mesh.uvs.empty();
    layout.patchIds = !mesh.patchIds.empty() &&
                      std::all_of(mesh.patchIds.begin(), mesh.patchIds.end(), glbPatchIdFits);
    layout.faces = triangleFace != nullptr;
    layout.instances = instances;
    glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-lo);
    for (const glm::vec3& p : mesh.positions) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    layout.min = lo;
    layout.max = hi;
    const MeshOfFace meshOfFace(instances);
    const std::map<uint32_t, std::vector<uint32_t>> groups = trianglesByFace(mesh, triangleFace);
    for (const auto& group : groups)
      layout.primitives.push_back({group.first, 3 * group.second.size(), meshOfFace(group.first)});

    bin.reserve(size_t(glbBinLength(layout)));
    appendValues(bin, mesh.positions);
    if (layout.normals) appendValues(bin, unitNormals(mesh));
    if (layout.uvs) appendValues(bin, mesh.uvs);
    if (layout.patchIds) {
      const std::vector<float> ids(mesh.patchIds.begin(), mesh.patchIds.end());
      appendValues(bin, ids);
    }
    std::vector<uint32_t> indices;
    for (const auto& group : groups) {
      padTo4(bin, 0);
      indices.clear();
      for (uint32_t t : group.second)
        for (int corner = 0; corner < 3; ++corner) indices.push_back(mesh.indices[3 * size_t(t) + corner]);
      appendGlbIndices(bin, indices.data(), indices.size(), layout.shortIndices());
    }
    padTo4(bin, 0);
  }
  writeGlbContainer(out, glbJsonChunk(layout), bin.size(), [&](std::ostream& to) {
    to.write(bin.data(), std::streamsize(bin.size()));
  });
}

void writeGlbFile(const std::string& path, const TriangleMesh& mesh,
                  const std::vector<uint32_t>* triangleFace, const GlbInstances* instances) {
  writeFileAtomically(path,
                      [&](std::ostream& out) { writeGlb(out, mesh, triangleFace, instances); });
}

}  // namespace tessera
