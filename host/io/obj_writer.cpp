// OBJ text output. Lines are assembled in a string and handed to the stream in large blocks:
// operator<< per number is several times slower and would follow the stream's locale.
#include "io/obj_writer.h"

#include <charconv>
#include <cstdint>

#include "io/atomic_file.h"

namespace tessera {
namespace {

class LineBuilder {
 public:
  explicit LineBuilder(std::ostream& out) : out_(out) { text_.reserve(kFlushSize + 256); }
  void put(const char* literal) { text_ += literal; }
  void put(char c) { text_ += c; }

  // Shortest representation that parses back to exactly `value` (float: at most 9 significant
  // digits; double: at most 17).
  template <typename Real>
  void putReal(Real value) {
    char digits[32];
    auto result = std::to_chars(digits, digits + sizeof digits, value);
    text_.append(digits, result.ptr);
  }

  void putInteger(uint64_t value) {
    char digits[24];
    auto result = std::to_chars(digits, digits + sizeof digits, value);
    text_.append(digits, result.ptr);
  }

  void endLine() {
    text_ += '\n';
    if (text_.size() >= kFlushSize) flush();
  }

  void flush() {
    out_.write(text_.data(), static_cast<std::streamsize>(text_.size()));
    text_.clear();
  }

 private:
  static constexpr size_t kFlushSize = 1 << 20;
  std::ostream& out_;
  std::string text_;
};

template <typename Vec3>
void putVec3(LineBuilder& line, const char* tag, const Vec3& v) {
  line.put(tag);
  line.put(' ');
  line.putReal(v.x);
  line.put(' ');
  line.putReal(v.y);
  line.put(' ');
  line.putReal(v.z);
  line.endLine();
}

// Positions or normals at the asked precision: the double copies where the mesh has them.
void putVectors(LineBuilder& line, const char* tag, const std::vector<glm::vec3>& floats,
                const std::vector<glm::dvec3>& doubles, MeshPrecision precision) {
  if (precision == MeshPrecision::Float) {
    for (const glm::vec3& p : floats) putVec3(line, tag, p);
  } else if (!doubles.empty()) {
    for (const glm::dvec3& p : doubles) putVec3(line, tag, p);
  } else {
    for (const glm::vec3& p : floats) putVec3(line, tag, glm::dvec3(p));
  }
}

// One "f" line (the forms of obj_writer.h) of three 0-based corners.
void putFace(LineBuilder& line, const uint32_t* corners, bool hasUvs, bool hasNormals) {
  line.put('f');
  for (int corner = 0; corner < 3; ++corner) {
    const uint64_t index = uint64_t(corners[corner]) + 1;  // OBJ counts from 1
    line.put(' ');
    line.putInteger(index);
    if (hasUvs || hasNormals) {
      line.put('/');
      if (hasUvs) line.putInteger(index);
      if (hasNormals) {
        line.put('/');
        line.putInteger(index);
      }
    }
  }
  line.endLine();
}

}  // namespace

void writeObjComment(std::ostream& out, uint64_t vertices, uint64_t triangles) {
  LineBuilder line(out);
  line.put("# Tessera triangle mesh: ");
  line.putInteger(vertices);
  line.put(" vertices, ");
  line.putInteger(triangles);
  line.put(" triangles");
  line.endLine();
  line.flush();
}

void writeObjVectors(std::ostream& out, const char* tag, const std::vector<glm::vec3>& values) {
  LineBuilder line(out);
  for (const glm::vec3& p : values) putVec3(line, tag, p);
  line.flush();
}

void writeObjUvs(std::ostream& out, const std::vector<glm::vec2>& uvs) {
  LineBuilder line(out);
  for (const glm::vec2& uv : uvs) {
    line.put("vt ");
    line.putReal(uv.x);
    line.put(' ');
    line.putReal(uv.y);
    line.endLine();
  }
  line.flush();
}

void writeObjFaces(std::ostream& out, const std::vector<uint32_t>& indices, bool hasUvs,
                   bool hasNormals) {
  LineBuilder line(out);
  for (size_t k = 0; k + 2 < indices.size(); k += 3) putFace(line, &indices[k], hasUvs, hasNormals);
  line.flush();
}

void writeObj(std::ostream& out, const TriangleMesh& mesh, const MeshWriteOptions& options) {
  mesh.validate();
  const bool hasUvs = !mesh.uvs.empty();
  const bool hasNormals = !mesh.normals.empty();
  writeObjComment(out, mesh.vertexCount(), mesh.triangleCount());
  {
    LineBuilder line(out);
    putVectors(line, "v", mesh.positions, mesh.positionsDouble, options.precision);
    line.flush();
  }
  writeObjUvs(out, mesh.uvs);
  LineBuilder line(out);
  putVectors(line, "vn", mesh.normals, mesh.normalsDouble, options.precision);
  const bool groups = options.metadata && !mesh.trianglePatchIds.empty();
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    // A group line where the patch changes; OBJ readers merge groups of one name.
    if (groups && (t == 0 || mesh.trianglePatchIds[t] != mesh.trianglePatchIds[t - 1])) {
      line.put("g patch_");
      line.putInteger(mesh.trianglePatchIds[t]);
      line.endLine();
    }
    putFace(line, &mesh.indices[3 * t], hasUvs, hasNormals);
  }
  line.flush();
}

void writeObjFile(const std::string& path, const TriangleMesh& mesh,
                  const MeshWriteOptions& options) {
  writeFileAtomically(path, [&](std::ostream& out) { writeObj(out, mesh, options); });
}

}  // namespace tessera
