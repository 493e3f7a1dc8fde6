// The topology checks over a parsed polygon mesh (validateTriangles, validateNoIsolatedVertices,
// validateManifold); rules in obj_reader.h.
#include <algorithm>
#include <map>
#include <cstdint>
#include <numeric>
#include <string>
#include <unordered_map>
#include <vector>

#include "io/errors.h"
#include "io/obj_reader.h"

namespace tessera {
namespace {

int faceLine(const PolygonMesh& mesh, size_t face) {
  return face < mesh.faceLines.size() ? mesh.faceLines[face] : 0;
}

// "faces 1 and 2 (lines 5 and 9)", lines left out for a mesh built in code.
std::string facesNamed(const PolygonMesh& mesh, const std::vector<size_t>& faces) {
  auto list = [&](auto label) {
    std::string out;
    for (size_t k = 0; k < faces.size(); ++k) {
      if (k > 0) out += k + 1 == faces.size() ? " and " : ", ";
      out += std::to_string(label(faces[k]));
    }
    return out;
  };
  std::string out = "faces " + list([](size_t f) { return f + 1; });
  if (!mesh.faceLines.empty())
    out += " (lines " + list([&](size_t f) { return faceLine(mesh, f); }) + ")";
  return out;
}

// Union-find over face corners: the corners of one vertex joined through the edges their
// faces share form that vertex's fans.
struct CornerSets {
  std::vector<size_t> parent;
  explicit CornerSets(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  size_t root(size_t c) {
    while (parent[c] != c) c = parent[c] = parent[parent[c]];
    return c;
  }
  void join(size_t a, size_t b) { parent[root(a)] = root(b); }
};

}  // namespace

void validateTriangles(const PolygonMesh& mesh, const std::string& nameForMessages) {
  for (size_t f = 0; f < mesh.faces.size(); ++f)
    if (mesh.faces[f].size() != 3)
      throw InputError(InputErrorKind::Topology, nameForMessages, faceLine(mesh, f),
                       "face " + std::to_string(f + 1) + " has " +
                           std::to_string(mesh.faces[f].size()) +
                           " corners; only triangles are accepted here");
}

void validateNoIsolatedVertices(const PolygonMesh& mesh, const std::string& nameForMessages) {
  std::vector<char> used(mesh.positions.size(), 0);
  for (const auto& face : mesh.faces)
    for (uint32_t v : face)
      if (v < used.size()) used[v] = 1;
  for (size_t v = 0; v < used.size(); ++v)
    if (!used[v])
      throw InputError(InputErrorKind::Topology, nameForMessages,
                       v < mesh.vertexLines.size() ? mesh.vertexLines[v] : 0,
                       "vertex " + std::to_string(v + 1) +
                           " is used by no face (isolated vertices are not supported in a "
                           "control mesh)");
}

namespace {

// Faces with the same corners in any order: the same triangle twice (two-sided when the
// orientations are opposite, which the edge checks alone accept). Throws the InputError.
void checkRepeatedFaces(const PolygonMesh& mesh, const std::string& nameForMessages) {
  std::map<std::vector<uint32_t>, size_t> seen;
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    std::vector<uint32_t> corners = mesh.faces[f];
    std::sort(corners.begin(), corners.end());
    const auto [at, inserted] = seen.emplace(corners, f);
    if (inserted) continue;
    const size_t first = at->second;
    std::string vertices;
    for (uint32_t v : mesh.faces[first]) vertices += (vertices.empty() ? "" : ", ") + std::to_string(v + 1);
    const bool sameWinding = [&] {
      const auto& a = mesh.faces[first];
      const auto& b = mesh.faces[f];
      for (size_t shift = 0; shift < a.size(); ++shift) {
        bool equal = true;
        for (size_t k = 0; k < a.size() && equal; ++k) equal = a[k] == b[(k + shift) % b.size()];
        if (equal) return true;
      }
      return false;
    }();
    throw InputError(InputErrorKind::Topology, nameForMessages, faceLine(mesh, f),
                     facesNamed(mesh, {first, f}) + " have the same corners (vertices " +
                         vertices + ")" +
                         (sameWinding ? ": the same face twice"
                                      : " in opposite orientations: a two-sided face, a closed "
                                        "surface of no volume") +
                         "; not a manifold");
  }
}

}  // namespace

void validateManifold(const PolygonMesh& mesh, const std::string& nameForMessages) {
  checkRepeatedFaces(mesh, nameForMessages);
  struct EdgeUse {
    size_t firstFace = 0, secondFace = 0;
    size_t firstFromCorner = 0, firstToCorner = 0;  // the first face's corners on the edge
    int uses = 0;
    bool firstRunsUp = false;  // the first face runs the edge from the lower vertex index
  };
  std::unordered_map<uint64_t, EdgeUse> edges;
  auto fail = [&](size_t face, const std::string& reason) {
    throw InputError(InputErrorKind::Topology, nameForMessages, faceLine(mesh, face), reason);
  };
  std::vector<size_t> cornerFace;  // corner id → face; corner ids run face by face
  for (size_t f = 0; f < mesh.faces.size(); ++f)
    cornerFace.insert(cornerFace.end(), mesh.faces[f].size(), f);
  CornerSets fans(cornerFace.size());

  size_t firstCorner = 0;
  for (size_t f = 0; f < mesh.faces.size(); firstCorner += mesh.faces[f].size(), ++f) {
    const std::vector<uint32_t>& face = mesh.faces[f];
    for (size_t k = 0; k < face.size(); ++k) {
      if (face[k] >= mesh.positions.size())
        fail(f, "face " + std::to_string(f + 1) + " refers to vertex " +
                    std::to_string(face[k] + 1) + ", but there are " +
                    std::to_string(mesh.positions.size()));
      for (size_t j = 0; j < k; ++j)
        if (face[j] == face[k])
          fail(f, "face " + std::to_string(f + 1) + " uses vertex " +
                      std::to_string(face[k] + 1) + " twice: not a manifold surface");
    }
    for (size_t k = 0; k < face.size(); ++k) {
      const size_t next = (k + 1) % face.size();
      const uint32_t from = face[k];
      const uint32_t to = face[next];
      const uint32_t low = std::min(from, to), high = std::max(from, to);
      EdgeUse& use = edges[(uint64_t(low) << 32) | high];
      const std::string edgeName =
          "the edge between vertices " + std::to_string(low + 1) + " and " + std::to_string(high + 1);
      if (use.uses == 0) {
        use.firstFace = f;
        use.firstRunsUp = from < to;
        use.firstFromCorner = firstCorner + k;
        use.firstToCorner = firstCorner + next;
      } else if (use.uses == 1) {
        use.secondFace = f;
        // Consistently oriented neighbours run their common edge in opposite directions.
        if ((from < to) == use.firstRunsUp)
          fail(f, facesNamed(mesh, {use.firstFace, f}) + " both run " + edgeName +
                      " from vertex " + std::to_string(from + 1) + " to vertex " +
                      std::to_string(to + 1) +
                      ": inconsistent orientation (one of them is flipped)");
        // Opposite directions: this face's `from` is the first face's `to`, and vice versa.
        fans.join(firstCorner + k, use.firstToCorner);
        fans.join(firstCorner + next, use.firstFromCorner);
      } else {
        fail(f, edgeName + " is shared by more than two faces: " +
                    facesNamed(mesh, {use.firstFace, use.secondFace, f}) + "; not a manifold");
      }
      ++use.uses;
    }
  }

  // Around a manifold vertex the faces form one fan, each joined to the next by an edge. Two
  // fans meeting only at the vertex (a "bow tie", two cones tip to tip) make the surface touch
  // itself there, which the edge counts above cannot see.
  std::vector<size_t> fanOfVertex(mesh.positions.size(), SIZE_MAX);  // a corner of its first fan
  size_t corner = 0;
  for (size_t f = 0; f < mesh.faces.size(); ++f)
    for (uint32_t v : mesh.faces[f]) {
      const size_t here = corner++;
      if (fanOfVertex[v] == SIZE_MAX) {
        fanOfVertex[v] = here;
      } else if (fans.root(here) != fans.root(fanOfVertex[v])) {
        fail(f, "vertex " + std::to_string(v + 1) + " is shared by " +
                    facesNamed(mesh, {cornerFace[fanOfVertex[v]], f}) +
                    ", which are not joined by edges around it: the surface touches itself "
                    "at that vertex (a \"bow tie\"); not a manifold");
      }
    }
}

}  // namespace tessera
