#include "api/convert.h"

#include <cmath>
#include <string>
#include <utility>

#include <glm/gtc/type_ptr.hpp>

namespace tessera::api {

std::vector<BezierPatch> toBezierPatches(const std::vector<Patch>& patches) {
  std::vector<BezierPatch> result(patches.size());
  for (size_t k = 0; k < patches.size(); ++k) {
    const Patch& in = patches[k];
    const std::string what = "patch " + std::to_string(k);
    if (in.degreeU < 1 || in.degreeU > kMaxDegree || in.degreeV < 1 || in.degreeV > kMaxDegree)
      throw ArgumentError(what + ": degree " + std::to_string(in.degreeU) + "x" +
                          std::to_string(in.degreeV) + " is outside 1..7");
    const size_t count = size_t(in.degreeU + 1) * size_t(in.degreeV + 1);
    if (in.points.size() != 3 * count)
      throw ArgumentError(what + ": " + std::to_string(in.points.size()) +
                          " coordinates, expected " + std::to_string(3 * count) + " (" +
                          std::to_string(count) + " control points x y z)");
    if (!in.weights.empty() && in.weights.size() != count)
      throw ArgumentError(what + ": " + std::to_string(in.weights.size()) + " weights, expected " +
                          std::to_string(count) + " or none");
    BezierPatch& out = result[k];
    out.degreeU = in.degreeU;
    out.degreeV = in.degreeV;
    out.cp.resize(count);
    for (size_t i = 0; i < count; ++i)
      out.cp[i] = glm::dvec3(in.points[3 * i], in.points[3 * i + 1], in.points[3 * i + 2]);
    out.weights = in.weights;
  }
  return result;
}

std::vector<Patch> toPatches(const std::vector<BezierPatch>& patches) {
  std::vector<Patch> result(patches.size());
  for (size_t k = 0; k < patches.size(); ++k) {
    const BezierPatch& in = patches[k];
    Patch& out = result[k];
    out.degreeU = in.degreeU;
    out.degreeV = in.degreeV;
    out.points.reserve(3 * in.cp.size());
    for (const glm::dvec3& p : in.cp) out.points.insert(out.points.end(), {p.x, p.y, p.z});
    out.weights = in.weights;
  }
  return result;
}

namespace {

// The public mesh's flat float arrays from glm vectors of N floats, which glm lays out packed
// (the static_asserts), so the copy is one block; the source is freed at once, so a call's
// peak holds one copy of each array at a time.
template <class Vector>
std::vector<float> flattened(std::vector<Vector>& source) {
  static_assert(sizeof(Vector) == Vector::length() * sizeof(float), "glm packs its vectors");
  const float* first = source.empty() ? nullptr : glm::value_ptr(source[0]);
  std::vector<float> flat(first, first + Vector::length() * source.size());
  std::vector<Vector>().swap(source);
  return flat;
}

}  // namespace

Mesh toMesh(TriangleMesh&& mesh) {
  Mesh out;
  out.positions = flattened(mesh.positions);
  out.normals = flattened(mesh.normals);
  out.uvs = flattened(mesh.uvs);
  out.patchIds = std::move(mesh.patchIds);
  out.indices = std::move(mesh.indices);
  return out;
}

QuadtreeOptions toQuadtreeOptions(const RuleOptions& options) {
  static_assert(
      int(Rule::A) == int(SplitRule::UniformGrid) && int(Rule::D) == int(SplitRule::TrueMax) &&
          int(Rule::T) == int(SplitRule::Tolerance),
      "Rule and SplitRule list the rules in the same order");
  QuadtreeOptions q;
  q.rule = static_cast<SplitRule>(options.rule);
  q.linearity = options.linearity;
  q.flatness = options.flatness;
  q.gridU = options.gridU;
  q.gridV = options.gridV;
  q.samples = options.samples;
  // 0 asks for the rule's default depth: the library's (12), or rule T's deeper limit.
  if (options.maxDepth != 0)
    q.maxDepth = options.maxDepth;
  else if (q.rule == SplitRule::Tolerance)
    q.maxDepth = kToleranceMaxDepth;
  q.nodeBudget = options.maxNodes;
  q.tolerance = options.tolerance;
  return q;
}

Camera toCamera(const View& view) {
  Camera camera;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      camera.viewProjection[c][r] = view.viewProjection[size_t(4 * c + r)];
  camera.width = view.width;
  camera.height = view.height;
  return camera;
}

double nearPlaneW(const glm::dmat4& m, double fallback) {
  // Rows z and w of the matrix (column-major: m[column][row]); z = a·w + b for every point
  // exactly when z's xyz part is a times w's.
  const glm::dvec3 z(m[0][2], m[1][2], m[2][2]), w(m[0][3], m[1][3], m[2][3]);
  const double ww = glm::dot(w, w);
  if (!(ww > 0)) return fallback;
  const double a = glm::dot(z, w) / ww;
  if (!(glm::length(z - a * w) <= 1e-9 * glm::length(z)) || a == 0) return fallback;
  const double b = m[3][2] - a * m[3][3];
  const double near = -b / a;
  return std::isfinite(near) && near > 0 ? near : fallback;
}

}  // namespace tessera::api
