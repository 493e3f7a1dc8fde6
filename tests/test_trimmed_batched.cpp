// The trimmed mesher's batched path (host/trim/face_tessellation.h, mesher.cpp): all faces'
// quad-trees built together, faces cut in parallel. Checks: each face's triangles are the ones
// it gets when meshed alone (the trees do not weld faces), bit for bit, with and without the
// trim pass; the thread count changes nothing; a closed model stays closed and within δ; one
// FreeCAD IDF model meshes closed-edged and within δ; Vulkan equals the mirror bit for bit.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <optional>

#include "gpu_test_context.h"
#include "mesh/tessellate.h"
#include "mesh_checks.h"
#include "trim/face_surface.h"
#include "trim/face_tessellation.h"
#include "trim/mesher.h"
#include "trimmed_models.h"
#ifdef TESSERA_HAVE_CAD
#include <BRepBndLib.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>

#include "cad/cad_file.h"
#include "cad/to_trimmed.h"
#endif

using namespace tessera;
using namespace tessera::test;

namespace {

// A unit cube whose top is a bicubic bump (a general-kind and a bicubic-kind tree), and apart
// from it a bump trimmed to a small disc (most of its quad-tree outside the loop).
TrimmedModel bumpyCubeAndDisc(bool withDisc) {
  TrimmedModel model;
  test::SharedPoints shared(model);
  const glm::dvec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const glm::dvec3 du = axes[(axis + 1) % 3], dv = axes[(axis + 2) % 3];
      BezierPatch p = planarPatch(double(side) * axes[axis], du, dv);
      bool reversed = glm::dot(glm::cross(du, dv), (side ? 1.0 : -1.0) * axes[axis]) < 0;
      if (axis == 2 && side == 1) {  // the top, z = 1: a bump over the same square
        p = bumpPatch(1, 0.3, 0.4);
        for (glm::dvec3& c : p.cp) c.z += 1;
        reversed = false;
      }
      const auto at = [&](glm::dvec2 uv) { return patchPoint(p, uv.x, uv.y); };
      model.faces.push_back(faceOf(p, {sampledLoop(squareBoundary(), 24, at, shared)}, reversed,
                                   uint32_t(model.faces.size())));
    }
  if (withDisc) {
    BezierPatch p = bumpPatch(1, 0.4, 0.2);
    for (glm::dvec3& c : p.cp) c.x += 3;
    const auto at = [&](glm::dvec2 uv) { return patchPoint(p, uv.x, uv.y); };
    model.faces.push_back(faceOf(p, {sampledLoop(circle({0.4, 0.55}, 0.2, true), 96, at, shared)},
                                 false, uint32_t(model.faces.size())));
  }
  return model;
}

TrimmedMesh meshWith(const TrimmedModel& model, double delta, bool trim, unsigned threads,
                     Backend& backend, TrimClassifier* trimClassifier = nullptr,
                     std::optional<ModelFrame> frame = std::nullopt) {
  TrimmedMeshOptions options;
  options.tolerance = delta;
  options.trimQuadtree = trim;
  options.threads = threads;
  options.frame = frame;
  return meshTrimmedModel(model, options, backend, trimClassifier);
}

// Face f's triangles as corner positions, in emission order.
std::vector<glm::vec3> faceCorners(const TrimmedMesh& m, size_t f) {
  std::vector<glm::vec3> out;
  for (size_t t = 0; t < m.triangleFace.size(); ++t)
    if (m.triangleFace[t] == f)
      for (int k = 0; k < 3; ++k) out.push_back(m.mesh.positions[m.mesh.indices[3 * t + k]]);
  return out;
}

// The largest parametric deviation re-measured at n = 10 from the emitted fp32 positions.
double remeasure(const TrimmedModel& model, const TrimmedMesh& m) {
  std::vector<FaceSurface> surfaces(model.faces.begin(), model.faces.end());
  double worst = 0;
  const int n = 10;
  for (size_t t = 0; t < m.triangleFace.size(); ++t)
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const double w[3] = {double(i) / n, double(j) / n, double(n - i - j) / n};
        glm::dvec2 uv(0);
        glm::dvec3 p(0);
        for (int k = 0; k < 3; ++k) {
          uv += w[k] * m.cornerUv[3 * t + k];
          p += w[k] * glm::dvec3(m.mesh.positions[m.mesh.indices[3 * t + k]]);
        }
        // The distance to the surface (from the same-uv guess), what the gap refinement holds
        // to δ by default (GapMeasure::Geometric); the parametric one may pass δ slightly there.
        worst = std::max(worst, surfaces[m.triangleFace[t]].distance(p, uv));
      }
  return worst;
}

bool sameMesh(const TrimmedMesh& a, const TrimmedMesh& b) {
  return a.mesh.indices == b.mesh.indices && a.mesh.positions == b.mesh.positions &&
         a.triangleFace == b.triangleFace && a.cornerUv == b.cornerUv;
}

// The Vulkan mesh against the mirror's: bit for bit where the device rounds as the mirror does.
// Elsewhere its positions move by fp32 roundings and the gap triangulation's choices with them
// (on an H100 the same 942 triangles, ordered otherwise): the mesh must then stand on its own,
// with the mirror's open edges (the B-rep edges are discretised on the host), no edge used
// three times or twice the same way, and within δ re-measured.
void checkVulkanMesh(const TrimmedModel& model, double delta, const TrimmedMesh& mirror,
                     const TrimmedMesh& vulkan) {
  if (exactMirrorArithmetic()) {
    CHECK(sameMesh(mirror, vulkan));
    return;
  }
  const EdgeCensus a = censusOf(mirror.mesh, 0), b = censusOf(vulkan.mesh, 0);
  const double worst = remeasure(model, vulkan);
  WARN("Vulkan's own mesh: " << b.boundaryEdges << " open edges (mirror " << a.boundaryEdges
                             << "), " << b.overusedEdges << " over-used, " << b.inconsistentEdges
                             << " inconsistent; distance " << worst << " (δ " << delta << ")");
  CHECK(b.boundaryEdges == a.boundaryEdges);
  CHECK(b.overusedEdges == 0);
  CHECK(b.inconsistentEdges == 0);
  CHECK(worst <= delta);
}

}  // namespace

TEST_CASE("trimmed batch: each face meshes as it does alone, whatever the threads",
          "[trim][trim-batch]") {
  const double delta = 2e-3;
  const TrimmedModel model = bumpyCubeAndDisc(true);
  Backend cpu = makeMirrorBackend();
  for (bool trim : {false, true}) {
    const TrimmedMesh all = meshWith(model, delta, trim, 0, cpu);
    WARN("trim pass " << trim << ": " << all.mesh.triangleCount() << " triangles, "
                      << all.timings.trees << " trees, " << all.timings.leaves << " leaves, "
                      << all.timings.trimmedAwayLeaves << " trimmed away");
    CHECK(all.timings.trees == 2);  // bicubic faces, general faces
    if (trim) CHECK(all.timings.trimmedAwayLeaves > 0);
    size_t differing = 0;
    for (size_t f = 0; f < model.faces.size(); ++f) {
      TrimmedModel alone;
      alone.sharedPoints = model.sharedPoints;
      alone.faces = {model.faces[f]};
      // In the model's frame (model_frame.h): a face alone has a frame of its own.
      const TrimmedMesh one =
          meshWith(alone, delta, trim, 1, cpu, nullptr, trimmedModelFrame(model));
      const std::vector<glm::vec3> batched = faceCorners(all, f), single = faceCorners(one, 0);
      differing += batched != single;
      CHECK(all.faces[f].triangles == one.faces[0].triangles);
      CHECK(all.faces[f].quadtreeTriangles == one.faces[0].quadtreeTriangles);
    }
    WARN("  faces whose triangles differ from the face meshed alone: " << differing);
    CHECK(differing == 0);
    const TrimmedMesh serial = meshWith(model, delta, trim, 1, cpu);
    CHECK(sameMesh(all, serial));
  }
}

TEST_CASE("trimmed batch: a closed model stays closed and within δ, trim pass on or off",
          "[trim][trim-batch]") {
  const double delta = 1e-3;
  const TrimmedModel model = bumpyCubeAndDisc(false);
  Backend cpu = makeMirrorBackend();
  for (bool trim : {false, true}) {
    const TrimmedMesh m = meshWith(model, delta, trim, 0, cpu);
    const EdgeCensus c = censusOf(m.mesh, 1e-14);
    const double worst = remeasure(model, m);
    WARN("bumpy cube, trim pass " << trim << ": " << m.mesh.triangleCount() << " triangles, "
                                  << c.boundaryEdges << " boundary, " << c.overusedEdges
                                  << " over-used, " << c.inconsistentEdges
                                  << " inconsistent edges; re-measured deviation " << worst);
    CHECK(c.boundaryEdges == 0);
    CHECK(c.overusedEdges == 0);
    CHECK(c.inconsistentEdges == 0);
    CHECK(c.degenerateTriangles == 0);
    CHECK(worst <= delta);
    for (const TrimmedFaceStats& s : m.faces) {
      CHECK(s.measuredTriangles == s.triangles);
      CHECK(s.maxGeometricDeviation <= delta);
    }
  }
  // Without measuring the kept triangles: the same mesh, only the gap ones measured.
  TrimmedMeshOptions options;
  options.tolerance = delta;
  options.measureKeptTriangles = false;
  const TrimmedMesh light = meshTrimmedModel(model, options, cpu);
  options.measureKeptTriangles = true;
  CHECK(sameMesh(light, meshTrimmedModel(model, options, cpu)));
  for (const TrimmedFaceStats& s : light.faces) CHECK(s.measuredTriangles == s.gapTriangles);
}

TEST_CASE("trimmed batch: Vulkan gives the mirror's mesh bit for bit", "[trim][trim-batch][gpu]") {
  const double delta = 2e-3;
  const TrimmedModel model = bumpyCubeAndDisc(true);
  Backend cpu = makeMirrorBackend();
  Backend vulkan = makeVulkanBackend(gpuContext(), 0);  // every level on the device
  const auto vulkanTrim = makeVulkanTrimClassifier(gpuContext());
  const TrimmedMesh a = meshWith(model, delta, true, 0, cpu);
  const TrimmedMesh b = meshWith(model, delta, true, 0, vulkan, vulkanTrim.get());
  float largest = 0;
  if (a.mesh.positions.size() == b.mesh.positions.size())
    for (size_t i = 0; i < a.mesh.positions.size(); ++i)
      largest = std::max(largest, glm::length(a.mesh.positions[i] - b.mesh.positions[i]));
  WARN("on " << gpuContext().info().name << ": mirror " << a.mesh.triangleCount()
             << " triangles, Vulkan " << b.mesh.triangleCount()
             << "; largest position difference " << largest);
  CHECK(a.timings.leaves == b.timings.leaves);
  CHECK(a.timings.trimmedAwayLeaves == b.timings.trimmedAwayLeaves);
  checkVulkanMesh(model, delta, a, b);
}

#ifdef TESSERA_HAVE_CAD
namespace {

// Open CASCADE's word on closure: the shape checks valid and every edge that is not a pole
// bounds exactly two face uses.
bool occtSaysClosed(const TopoDS_Shape& shape) {
  if (!BRepCheck_Analyzer(shape).IsValid()) return false;
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  if (edgeFaces.Extent() == 0) return false;
  for (int e = 1; e <= edgeFaces.Extent(); ++e)
    if (!BRep_Tool::Degenerated(TopoDS::Edge(edgeFaces.FindKey(e))) &&
        edgeFaces.FindFromIndex(e).Extent() != 2)
      return false;
  return true;
}

}  // namespace

TEST_CASE("trimmed batch: an IDF model meshes closed (OCCT: closed) and within δ",
          "[trim][trim-batch][cad]") {
  const std::string path = "/usr/share/freecad/Mod/Idf/Idflibs/0603_SMD.stp";
  if (!std::filesystem::exists(path)) {
    WARN("skipped: " << path << " not installed (freecad-common)");
    return;
  }
  const CadFile file = readCadFile(path);
  Bnd_Box box;
  BRepBndLib::Add(file.shape, box);
  const CadImport import = toTrimmedModel(file, 1e-3 * std::sqrt(box.SquareExtent()));
  REQUIRE(import.failures.empty());
  Backend cpu = makeMirrorBackend();
  TrimmedMeshOptions options;
  options.tolerance = import.delta;
  options.measureGeometric = false;
  const TrimmedMesh m = meshTrimmedModel(import.model, options, cpu);
  const EdgeCensus c = censusOf(m.mesh, 0);
  const double worst = remeasure(import.model, m);
  size_t gapFailures = 0;
  double worstStat = 0;
  for (const TrimmedFaceStats& s : m.faces)
    gapFailures += s.gapFailures, worstStat = std::max(worstStat, s.maxParametricDeviation);
  const bool closed = occtSaysClosed(file.shape);
  WARN(path << " (OCCT: " << (closed ? "closed" : "open") << ") at δ " << import.delta << ": " << import.model.faces.size() << " faces, "
                     << m.mesh.triangleCount() << " triangles, " << c.boundaryEdges
                     << " boundary, " << c.overusedEdges << " over-used, "
                     << c.inconsistentEdges << " inconsistent edges, " << gapFailures
                     << " gap failures; parametric deviation " << worstStat << ", distance re-measured " << worst
                     << "; " << m.timings.trees << " trees, " << m.timings.trimmedAwayLeaves
                     << " of " << m.timings.leaves << " leaves trimmed away");
  CHECK(gapFailures == 0);
  CHECK(closed);
  CHECK(c.boundaryEdges == 0);
  CHECK(c.overusedEdges == 0);
  CHECK(c.inconsistentEdges == 0);
  // The distance to the surface is the promise: on cylinders, cones, spheres and tori rule T's
  // leaves are proven by it (trim/revolution_bound.h), so the parametric stat is printed only.
  CHECK(worst <= import.delta);
}

// The revolution bound decides those faces' nodes on the host after the backend's own
// decisions, so the Vulkan tree and mesh are still the mirror's, bit for bit, on a model with
// spheres and cylinders.
TEST_CASE("trimmed batch: Vulkan gives the mirror's mesh on an IDF model with spheres and cylinders",
          "[trim][trim-batch][cad][gpu]") {
  const std::string path = "/usr/share/freecad/Mod/Idf/Idflibs/1206_SMD.stp";
  REQUIRE(std::filesystem::exists(path));  // freecad-common (scripts/deps.sh)
  const CadFile file = readCadFile(path);
  const CadImport import = toTrimmedModel(file, defaultCadTolerance(file.shape));
  size_t revolution = 0;
  for (const TrimmedFace& face : import.model.faces)
    revolution += face.revolution.profile != RevolutionForm::Profile::None;
  Backend cpu = makeMirrorBackend();
  Backend vulkan = makeVulkanBackend(gpuContext());
  const auto vulkanTrim = makeVulkanTrimClassifier(gpuContext());
  const TrimmedMesh a = meshWith(import.model, import.delta, true, 0, cpu);
  const TrimmedMesh b = meshWith(import.model, import.delta, true, 0, vulkan, vulkanTrim.get());
  WARN("on " << gpuContext().info().name << ": 1206_SMD, " << revolution << " of "
             << import.model.faces.size() << " faces by the revolution bound; mirror "
             << a.mesh.triangleCount() << " triangles, Vulkan " << b.mesh.triangleCount());
  CHECK(revolution >= 28);  // 20 cylinders and 8 spheres
  CHECK(a.timings.leaves == b.timings.leaves);
  checkVulkanMesh(import.model, import.delta, a, b);
}
#endif
