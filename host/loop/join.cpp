#include "loop/join.h"

#include <cmath>
#include <stdexcept>

#include "loop/bvh.h"
#include "loop/detail/bridge.h"
#include "loop/limit.h"
#include "loop/local_refine.h"

namespace tessera {
namespace {

TriangleBvh bvhOf(const LoopShape& s) { return TriangleBvh(s.positions, s.topology.triangles); }

double area(const LoopShape& s, uint32_t f) {
  const auto& t = s.topology.triangles;
  const auto& p = s.positions;
  return 0.5 * glm::length(glm::cross(p[t[3 * f + 1]] - p[t[3 * f]], p[t[3 * f + 2]] - p[t[3 * f]]));
}

// Flags of the faces of `mesh` that intersect a face of `other`, and their mean area.
std::vector<uint8_t> interfering(const LoopShape& mesh, const LoopShape& other, double* meanArea) {
  std::vector<uint8_t> flags(mesh.topology.triangles.size() / 3, 0);
  bvhOf(mesh).forEachIntersecting(bvhOf(other), [&](uint32_t f, uint32_t) { flags[f] = 1; });
  double sum = 0;
  size_t count = 0;
  for (uint32_t f = 0; f < flags.size(); ++f)
    if (flags[f]) sum += area(mesh, f), ++count;
  if (meanArea) *meanArea = count ? sum / double(count) : 0.0;
  return flags;
}

// The paper's rule (§3.1): triangles of `mesh` that intersect `other` or, if `other` is closed,
// lie inside it.
std::vector<uint8_t> facesToRemove(const LoopShape& mesh, const LoopShape& other) {
  std::vector<uint8_t> remove = interfering(mesh, other, nullptr);
  if (!buildLoopTopology(other.topology).closed()) return remove;  // no inside: largest piece
  const TriangleBvh otherBvh = bvhOf(other);
  const auto& t = mesh.topology.triangles;
  for (uint32_t f = 0; f < remove.size(); ++f)
    if (!remove[f]) {
      const glm::dvec3 centre =
          (mesh.positions[t[3 * f]] + mesh.positions[t[3 * f + 1]] + mesh.positions[t[3 * f + 2]]) / 3.0;
      remove[f] = otherBvh.inside(centre);
    }
  return remove;
}

int defaultLevels(double mine, double theirs) {
  if (mine <= 0 || theirs <= 0) return 1;
  return 1 + std::max(0, int(std::lround(std::log(mine / theirs) / std::log(4.0))));
}

}  // namespace

LoopJoinResult joinLoopMeshes(const LoopShape& a, const LoopShape& b,
                              const LoopJoinOptions& options) {
  const LoopTopology topologyA = buildLoopTopology(a.topology);
  const LoopTopology topologyB = buildLoopTopology(b.topology);
  LoopJoinResult result;
  LoopJoinReport& report = result.report;
  double areaA = 0, areaB = 0;
  const auto firstA = interfering(a, b, &areaA), firstB = interfering(b, a, &areaB);
  for (uint8_t f : firstA) report.interferingA += f;
  for (uint8_t f : firstB) report.interferingB += f;
  if (report.interferingA == 0)
    throw std::invalid_argument("join: " + a.name + " and " + b.name + " do not intersect");
  for (const int levels : {options.levelsA, options.levelsB})
    if (levels < -1 || levels > kMaxLoopJoinLevels)
      throw std::invalid_argument("join: local refinement levels must be 0.." +
                                  std::to_string(kMaxLoopJoinLevels) + " (or -1: by area), got " +
                                  std::to_string(levels));
  report.levelsA = options.levelsA >= 0 ? options.levelsA : defaultLevels(areaA, areaB);
  report.levelsB = options.levelsB >= 0 ? options.levelsB : defaultLevels(areaB, areaA);
  report.trianglesIn = (a.topology.triangles.size() + b.topology.triangles.size()) / 3;

  // (1) Local refinement, both sides in turn against the other's current mesh. Vertices keep
  // their indices: new ones are appended, so index < input count means an input vertex.
  // Flags sized to the inputs: with 0 levels no refinement fills them, yet step (3) reads them.
  LocalRefinement ra{a, std::vector<uint8_t>(a.topology.vertexCount, 0)},
      rb{b, std::vector<uint8_t>(b.topology.vertexCount, 0)};
  for (int level = 0; level < std::max(report.levelsA, report.levelsB); ++level) {
    if (level < report.levelsA) ra = refineLocally(ra.mesh, interfering(ra.mesh, rb.mesh, nullptr), ra.refined);
    if (level < report.levelsB) rb = refineLocally(rb.mesh, interfering(rb.mesh, ra.mesh, nullptr), rb.refined);
  }
  // (2) Removal of what crosses or lies inside the other side.
  const auto removeA = facesToRemove(ra.mesh, rb.mesh), removeB = facesToRemove(rb.mesh, ra.mesh);
  std::vector<uint32_t> keptA, keptB;
  const LoopShape cutA = removeFaces(ra.mesh, removeA, keptA, a.name);
  const LoopShape cutB = removeFaces(rb.mesh, removeB, keptB, b.name);
  report.removedA = ra.mesh.topology.triangles.size() / 3 - cutA.topology.triangles.size() / 3;
  report.removedB = rb.mesh.topology.triangles.size() / 3 - cutB.topology.triangles.size() / 3;
  const auto loopsA = boundaryLoops(cutA.topology), loopsB = boundaryLoops(cutB.topology);
  const size_t openA = buildLoopTopology(a.topology).closed() ? 0 : 1;  // a pasted part's rim
  if (loopsA.size() != 1 || loopsB.size() != 1)
    throw std::invalid_argument("join: the intersection leaves " + std::to_string(loopsA.size()) +
                             " boundary loops on " + a.name + " and " +
                             std::to_string(loopsB.size()) + " on " + b.name +
                             " (expected one each: the shapes must overlap in one region" +
                             (openA ? ", and the cut part's rim must lie inside the other" : "") +
                             ")");

  // (3) Merge and bridge.
  LoopShape& out = result.mesh;
  out.name = a.name + "+" + b.name;
  out.positions = cutA.positions;
  out.positions.insert(out.positions.end(), cutB.positions.begin(), cutB.positions.end());
  const uint32_t offset = uint32_t(cutA.positions.size());
  out.topology.triangles = cutA.topology.triangles;
  for (uint32_t i : cutB.topology.triangles) out.topology.triangles.push_back(i + offset);
  std::vector<uint32_t> loopB = loopsB[0];
  for (uint32_t& v : loopB) v += offset;
  const auto bridge = bridgeLoops(loopsA[0], loopB, out.positions);
  out.topology.triangles.insert(out.topology.triangles.end(), bridge.begin(), bridge.end());
  out.topology.vertexCount = uint32_t(out.positions.size());
  report.bridgeTriangles = bridge.size() / 3;
  report.trianglesOut = out.topology.triangles.size() / 3;
  const LoopTopology joined = buildLoopTopology(out.topology);  // throws unless a 2-manifold

  // Where each vertex came from, and which changed: refined, on the seam, or next to those.
  const uint32_t n = joined.vertexCount;
  result.source.assign(n, kLoopNone);
  result.side.assign(n, 0);
  std::vector<uint8_t> changed(n, 0);
  for (int s = 0; s < 2; ++s) {
    const auto& kept = s == 0 ? keptA : keptB;
    const auto& refined = s == 0 ? ra.refined : rb.refined;
    const uint32_t inputCount = (s == 0 ? a : b).topology.vertexCount;
    for (uint32_t old = 0; old < kept.size(); ++old) {
      if (kept[old] == kLoopNone) continue;
      const uint32_t v = kept[old] + (s == 0 ? 0 : offset);
      result.side[v] = uint8_t(s);
      if (old < inputCount) result.source[v] = old;
      changed[v] = refined[old] || old >= inputCount;
    }
  }
  for (size_t i = 0; i < bridge.size(); ++i) changed[bridge[i]] = 1;
  result.fitted = changed;
  for (uint32_t v = 0; v < n; ++v)
    if (changed[v])
      for (uint32_t j = 0; j < joined.valence(v); ++j) result.fitted[joined.ring(v)[j]] = 1;

  // (4) Fit the changed vertices back to their own side's original limit surface.
  const TriangleBvh surfaceA = loopLimitSurfaceBvh(topologyA, a.positions, options.limitSurfaceLevels);
  const TriangleBvh surfaceB = loopLimitSurfaceBvh(topologyB, b.positions, options.limitSurfaceLevels);
  std::vector<uint8_t> targetOf(n, 0);
  for (uint32_t v = 0; v < n; ++v) {
    targetOf[v] = result.fitted[v] ? uint8_t(1 + result.side[v]) : 0;
    report.fittedVertices += result.fitted[v];
  }
  report.unchangedVertices = n - report.fittedVertices;
  LoopFitOptions fit;
  fit.maxIterations = options.fitIterations;
  const LoopFitReport fitted = fitLoopToSurfaces(joined, out.positions, {&surfaceA, &surfaceB}, targetOf, fit);
  report.fitEnergyBefore = fitted.energy.front();
  report.fitEnergyAfter = fitted.energy.back();
  report.maxDeviation = fitted.maxDistance;
  return result;
}

LoopShape cutByPlane(const LoopShape& mesh, const glm::dvec3& normal, double offset) {
  const auto& t = mesh.topology.triangles;
  std::vector<uint8_t> remove(t.size() / 3, 0);
  for (uint32_t f = 0; f < remove.size(); ++f)
    for (int i = 0; i < 3; ++i) remove[f] |= glm::dot(normal, mesh.positions[t[3 * f + i]]) < offset;
  std::vector<uint32_t> kept;
  LoopShape part = removeFaces(mesh, remove, kept, mesh.name);
  part.name = mesh.name + " cut";
  return part;
}

LoopShape cutByVertices(const LoopShape& mesh, const std::vector<uint32_t>& chosen) {
  const uint32_t n = mesh.topology.vertexCount;
  std::vector<uint8_t> isChosen(n, 0);
  for (uint32_t v : chosen) {
    if (v >= n)
      throw std::invalid_argument("paste: vertex " + std::to_string(v) + " of " + mesh.name +
                                  " is past its " + std::to_string(n) + " vertices");
    isChosen[v] = 1;
  }
  const auto& t = mesh.topology.triangles;
  std::vector<uint8_t> remove(t.size() / 3, 0);
  size_t kept = 0;
  for (uint32_t f = 0; f < remove.size(); ++f) {
    remove[f] = !(isChosen[t[3 * f]] && isChosen[t[3 * f + 1]] && isChosen[t[3 * f + 2]]);
    kept += !remove[f];
  }
  if (kept == 0)
    throw std::invalid_argument("paste: the " + std::to_string(chosen.size()) +
                                " chosen vertices of " + mesh.name +
                                " hold no whole triangle (a triangle is pasted when all three "
                                "of its corners are chosen)");
  std::vector<uint32_t> keptVertex;
  LoopShape part = removeFaces(mesh, remove, keptVertex, mesh.name);
  // removeFaces keeps the largest piece (and the larger fan where pieces touch at a vertex):
  // anything it dropped was a second region the user chose.
  if (part.topology.triangles.size() / 3 != kept)
    throw std::invalid_argument(
        "paste: the " + std::to_string(kept) + " triangles of the chosen vertices of " +
        mesh.name + " are not one piece (the largest has " +
        std::to_string(part.topology.triangles.size() / 3) +
        "; pieces may also touch at a single vertex): choose one connected region");
  part.name = mesh.name + " part";
  return part;
}

}  // namespace tessera
