// OBJ parsing, statement by statement so every error can name its line. Format and rules:
// obj_reader.h; the topology checks over the parsed faces are in obj_topology.cpp.
#include "io/obj_reader.h"

#include <algorithm>
#include <limits>
#include <string_view>

#include "io/errors.h"
#include "io/input_limit.h"
#include "io/text_lines.h"

namespace tessera {
namespace {

bool isOneOf(std::string_view word, std::initializer_list<const char*> words) {
  for (const char* w : words)
    if (word == w) return true;
  return false;
}

// Display and grouping statements that carry nothing for a polygon mesh.
bool isIgnoredStatement(std::string_view keyword) {
  return isOneOf(keyword, {"vp", "g", "o", "s", "usemtl", "mtllib", "l", "p", "mg", "lod",
                           "bevel", "c_interp", "d_interp", "shadow_obj", "trace_obj", "maplib",
                           "usemap"});
}

bool isFreeFormStatement(std::string_view keyword) {
  return isOneOf(keyword, {"cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm",
                           "trim", "hole", "scrv", "sp", "end", "con"});
}

std::string ordinal(const char* noun, size_t oneBased) {
  return std::string(noun) + " " + std::to_string(oneBased);
}

// Index positive beyond the elements read so far: checked when the file is complete, since
// the OBJ specification numbers elements by their order in the whole file.
struct ForwardReference {
  long long index;  // as written, ≥ 1
  int line;
};

class ObjParser {
 public:
  ObjParser(std::istream& in, const std::string& name) : lines_(in, name) {}

  PolygonMesh parse() {
    while (lines_.next()) {
      std::vector<std::string_view> tokens = lines_.tokens();
      // A token starting with '#' begins a trailing comment.
      tokens.erase(std::find_if(tokens.begin(), tokens.end(),
                                [](std::string_view t) { return t.front() == '#'; }),
                   tokens.end());
      const std::string_view keyword = tokens.front();
      if (keyword == "v") {
        parseVertex(tokens);
      } else if (keyword == "f") {
        parseFace(tokens);
      } else if (keyword == "vt") {
        ++textureCount_;
      } else if (keyword == "vn") {
        ++normalCount_;
      } else if (isFreeFormStatement(keyword)) {
        lines_.fail(InputErrorKind::Syntax, "free-form geometry (" + quotedToken(keyword) +
                                                ") is not supported; only polygonal faces are read");
      } else if (!isIgnoredStatement(keyword)) {
        lines_.fail(InputErrorKind::Syntax, "unknown OBJ statement " + quotedToken(keyword));
      }
    }
    const int end = lines_.lineAfterEnd();
    if (mesh_.positions.empty() && mesh_.faces.empty())
      lines_.fail(InputErrorKind::Count, end, "empty mesh: no vertices (\"v\") and no faces (\"f\")");
    if (mesh_.positions.empty())
      lines_.fail(InputErrorKind::Count, end, "no vertices (\"v\" lines) for the faces");
    if (mesh_.faces.empty())
      lines_.fail(InputErrorKind::Count, end, "no faces (\"f\" lines): not a polygon mesh");
    checkForward(positionRefs_, mesh_.positions.size(), "vertex", "vertices");
    checkForward(textureRefs_, textureCount_, "texture-coordinate", "\"vt\" lines");
    checkForward(normalRefs_, normalCount_, "normal", "\"vn\" lines");
    return std::move(mesh_);
  }

 private:
  void parseVertex(const std::vector<std::string_view>& tokens) {
    const size_t numbers = tokens.size() - 1;
    const std::string vertexName = ordinal("vertex", mesh_.positions.size() + 1);
    if (numbers != 3 && numbers != 4 && numbers != 6)
      lines_.fail(InputErrorKind::Syntax,
                  "expected \"v x y z\" (3 numbers; 4 with a weight, 6 with a colour) for " +
                      vertexName + ", found " + std::to_string(numbers));
    if (mesh_.positions.size() >= std::numeric_limits<uint32_t>::max())
      lines_.fail(InputErrorKind::Range, "more vertices than 32-bit indices can address");
    static const char* const kNames[] = {"x", "y", "z", "w", "r", "g", "b"};
    glm::dvec3 p;
    for (size_t c = 0; c < numbers; ++c) {
      const char* component = numbers == 6 && c >= 3 ? kNames[c + 1] : kNames[c];
      const double value =
          parseCoordinate(lines_, tokens[c + 1], std::string(component) + " of " + vertexName);
      if (c < 3) p[static_cast<int>(c)] = value;
    }
    mesh_.positions.push_back(p);
    mesh_.vertexLines.push_back(lines_.line());
  }

  // One index of a corner: 1-based, negative counts back from the latest element.
  // Returns the 0-based index; a positive one beyond `countSoFar` is recorded in `forward`.
  uint32_t resolve(std::string_view token, std::string_view part, size_t countSoFar,
                   const char* noun, const std::string& cornerName,
                   std::vector<ForwardReference>& forward) {
    long long value = 0;
    bool outOfRange = false;
    if (!parseInteger(part, value, outOfRange))
      lines_.fail(InputErrorKind::Syntax, quotedToken(token) + " is not a face corner (" +
                                              cornerName +
                                              "; expected v, v/t, v//n or v/t/n with integers)");
    if (outOfRange || value > std::numeric_limits<uint32_t>::max() ||
        value < -static_cast<long long>(std::numeric_limits<uint32_t>::max()))
      lines_.fail(InputErrorKind::Topology, std::string(noun) + " index " + quotedToken(part) +
                                                " is out of range (" + cornerName + ")");
    if (value == 0)
      lines_.fail(InputErrorKind::Topology,
                  std::string(noun) + " index 0 is invalid (" + cornerName +
                      "): OBJ indices start at 1, negative ones count back from the latest");
    if (value < 0) {
      if (static_cast<unsigned long long>(-value) > countSoFar)
        lines_.fail(InputErrorKind::Topology,
                    "relative " + std::string(noun) + " index " + std::to_string(value) + " (" +
                        cornerName + ") reaches before the first one: " +
                        std::to_string(countSoFar) + " precede this line");
      return static_cast<uint32_t>(static_cast<long long>(countSoFar) + value);
    }
    if (static_cast<unsigned long long>(value) > countSoFar)
      forward.push_back({value, lines_.line()});
    return static_cast<uint32_t>(value - 1);
  }

  void parseFace(const std::vector<std::string_view>& tokens) {
    const size_t faceNumber = mesh_.faces.size() + 1;
    const std::string faceName = ordinal("face", faceNumber);
    const size_t corners = tokens.size() - 1;
    if (corners < 3)
      lines_.fail(InputErrorKind::Topology, faceName + " has " + std::to_string(corners) +
                                                " corner" + (corners == 1 ? "" : "s") +
                                                "; a face needs at least 3");
    std::vector<uint32_t> face;
    face.reserve(corners);
    int faceForm = -1;
    for (size_t k = 0; k < corners; ++k) {
      const std::string_view token = tokens[k + 1];
      const std::string cornerName = ordinal("corner", k + 1) + " of " + faceName;
      std::string_view parts[3];
      int slashes = 0;
      size_t start = 0;
      for (size_t i = 0; i <= token.size(); ++i) {
        if (i < token.size() && token[i] != '/') continue;
        if (slashes > 2)
          lines_.fail(InputErrorKind::Syntax, quotedToken(token) + " is not a face corner (" +
                                                  cornerName + "; expected v, v/t, v//n or v/t/n)");
        parts[slashes] = token.substr(start, i - start);
        start = i + 1;
        if (i < token.size()) ++slashes;
      }
      // Forms: 0 "v", 1 "v/t", 2 "v//n", 3 "v/t/n".
      const bool hasTexture = slashes >= 1 && !parts[1].empty();
      const bool hasNormal = slashes == 2;
      const int form = (hasTexture ? 1 : 0) + (hasNormal ? 2 : 0);
      if (slashes > 2 || (slashes == 1 && !hasTexture) || (hasNormal && parts[2].empty()))
        lines_.fail(InputErrorKind::Syntax, quotedToken(token) + " is not a face corner (" +
                                                cornerName + "; expected v, v/t, v//n or v/t/n)");
      if (faceForm >= 0 && form != faceForm)
        lines_.fail(InputErrorKind::Syntax, quotedToken(token) + " (" + cornerName +
                                                ") mixes corner forms: " + quotedToken(tokens[1]) +
                                                " began the face");
      faceForm = form;
      face.push_back(resolve(token, parts[0], mesh_.positions.size(), "vertex", cornerName,
                             positionRefs_));
      if (hasTexture)
        resolve(token, parts[1], textureCount_, "texture-coordinate", cornerName, textureRefs_);
      if (hasNormal) resolve(token, parts[2], normalCount_, "normal", cornerName, normalRefs_);
    }
    mesh_.faces.push_back(std::move(face));
    mesh_.faceLines.push_back(lines_.line());
  }

  void checkForward(const std::vector<ForwardReference>& refs, size_t count, const char* noun,
                    const char* plural) const {
    for (const ForwardReference& ref : refs)
      if (static_cast<unsigned long long>(ref.index) > count)
        lines_.fail(InputErrorKind::Topology, ref.line,
                    std::string(noun) + " index " + std::to_string(ref.index) +
                        " is out of range: the file has " + std::to_string(count) + " " + plural);
  }

  TextLines lines_;
  PolygonMesh mesh_;
  size_t textureCount_ = 0, normalCount_ = 0;
  std::vector<ForwardReference> positionRefs_, textureRefs_, normalRefs_;
};

}  // namespace

PolygonMesh parseObj(std::istream& in, const std::string& nameForMessages) {
  return ObjParser(in, nameForMessages).parse();
}

PolygonMesh readObj(const std::string& path) {
  std::ifstream file = openForReading(path, "an OBJ file");
  BoundedInput in(file, path);
  return parseObj(in.stream(), path);
}

}  // namespace tessera
