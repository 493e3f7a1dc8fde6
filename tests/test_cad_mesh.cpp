// Issue 17's "must show": every model of FreeCAD's IDF library meshed through host/cad/ and
// host/trim/ at the default δ (0.1% of its diagonal): a mesh for each, every face's measured
// distance to its own surface within δ (plus the offset of the face's trim points from it,
// where the file's edge curves and pcurves part), and the mesh closed — no
// boundary edge, no T-junction, no over-used edge, consistent orientation, no zero-area triangle —
// wherever Open CASCADE says the shape is closed (BRepCheck valid, every edge on two faces).
#include <catch2/catch.hpp>

#ifdef TESSERA_HAVE_CAD
#include <BRepCheck_Analyzer.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "cad/cad_file.h"
#include "cad/to_trimmed.h"
#include "cad_test_shapes.h"
#include "mesh/tessellate.h"
#include "mesh_checks.h"
#include "trim/mesher.h"

using namespace tessera;

namespace {

const char* kIdfLibrary = "/usr/share/freecad/Mod/Idf/Idflibs";

std::vector<std::string> idfModels() {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(kIdfLibrary)) {
    const std::string ext = entry.path().extension().string();
    if (ext == ".stp" || ext == ".igs") files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Open CASCADE's word on closure: the shape checks valid and every edge that is not a pole
// bounds exactly two face uses (a seam, twice in one face, counts as two).
bool occtSaysClosed(const TopoDS_Shape& shape) {
  if (!BRepCheck_Analyzer(shape).IsValid()) return false;
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  if (edgeFaces.Extent() == 0) return false;
  for (int e = 1; e <= edgeFaces.Extent(); ++e) {
    if (BRep_Tool::Degenerated(TopoDS::Edge(edgeFaces.FindKey(e)))) continue;
    if (edgeFaces.FindFromIndex(e).Extent() != 2) return false;
  }
  return true;
}

struct ModelFigures {
  size_t faces = 0, triangles = 0, closedModels = 0, models = 0;
  double worstOverDelta = 0;        // largest measured distance / δ
  double worstOffsetOverDelta = 0;  // largest trim-point offset / δ
  double worstParametricOverDelta = 0;
  std::string worstModel;
};

void meshModel(const CadFile& file, const std::string& name, Backend& backend, ModelFigures& all) {
  INFO(name);
  const double delta = defaultCadTolerance(file.shape);
  const CadImport import = toTrimmedModel(file, delta);
  CHECK(import.failures.empty());
  CHECK(import.emptyFaces.size() <= 2);  // SOD_323's two zero-area sliver faces (docs/cad.md)
  TrimmedMeshOptions options;
  options.tolerance = delta;
  const TrimmedMesh mesh = meshTrimmedModel(import.model, options, backend);
  REQUIRE(mesh.mesh.triangleCount() > 0);

  // The promise (docs/trimmed_faces.md): within δ of the face's surface, plus how far the
  // file itself puts the face's trim points off it (an edge whose 3D curve and pcurve part).
  // Geometric: the distance to the surface, what a CAD deflection means; the parametric
  // measure (same uv) is printed, not held to δ.
  for (const TrimmedFaceStats& f : mesh.faces) {
    INFO("face " << f.faceIndex << ", trim points off the surface by " << f.maxTrimPointOffset);
    CHECK(f.maxGeometricDeviation <= delta + f.maxTrimPointOffset);
    CHECK(f.gapFailures == 0);
    const double ratio = f.maxGeometricDeviation / delta;
    all.worstOffsetOverDelta = std::max(all.worstOffsetOverDelta, f.maxTrimPointOffset / delta);
    if (ratio > all.worstOverDelta) {
      all.worstOverDelta = ratio;
      all.worstModel = name;
    }
    all.worstParametricOverDelta = std::max(all.worstParametricOverDelta, f.maxParametricDeviation / delta);
  }

  const bool closed = occtSaysClosed(file.shape);
  const test::EdgeCensus census = test::censusOf(mesh.mesh, 0.0);
  CHECK(census.overusedEdges == 0);
  CHECK(census.inconsistentEdges == 0);
  if (closed) {
    // Open models are printed, not held: SOD_323 (two zero-area sliver faces OCCT cannot close)
    // gives one zero-area triangle at the slivers' edge, three points 1e-7 apart on one line.
    CHECK(census.degenerateTriangles == 0);
    CHECK(census.boundaryEdges == 0);
    CHECK(test::tJunctionCount(mesh.mesh, census, 1e-9 * delta / 1e-3) == 0);
  }
  WARN(name << ": " << mesh.faces.size() << " faces, " << mesh.mesh.triangleCount()
            << " triangles, δ " << delta << ", OCCT " << (closed ? "closed" : "open")
            << ", boundary edges " << census.boundaryEdges << ", zero-area triangles "
            << census.degenerateTriangles);
  all.models += 1;
  all.closedModels += closed;
  all.faces += mesh.faces.size();
  all.triangles += mesh.mesh.triangleCount();
}

// In three interleaved parts (files k, k + 3, ...): three CTest tests side by side, since
// reading STEP is most of the time.
void meshIdfPart(size_t part) {
  const std::vector<std::string> files = idfModels();
  REQUIRE(files.size() == 32);  // Debian's freecad-common (scripts/deps.sh installs it)
  Backend backend = makeMirrorBackend();
  ModelFigures all;
  for (size_t k = part; k < files.size(); k += 3)
    meshModel(readCadFile(files[k]), std::filesystem::path(files[k]).filename().string(), backend,
              all);
  WARN("IDF part " << part + 1 << "/3: " << all.models << " models (" << all.closedModels
                   << " closed by OCCT), " << all.faces << " faces, " << all.triangles
                   << " triangles; largest distance/δ " << all.worstOverDelta << " ("
                   << all.worstModel << "), trim points off by ≤ " << all.worstOffsetOverDelta
                   << " δ; parametric/δ " << all.worstParametricOverDelta);
}

}  // namespace

TEST_CASE("cad mesh: FreeCAD's IDF library within δ and closed where OCCT is (part 1 of 3)",
          "[cad][cad-mesh]") {
  meshIdfPart(0);
}
TEST_CASE("cad mesh: FreeCAD's IDF library within δ and closed where OCCT is (part 2 of 3)",
          "[cad][cad-mesh]") {
  meshIdfPart(1);
}
TEST_CASE("cad mesh: FreeCAD's IDF library within δ and closed where OCCT is (part 3 of 3)",
          "[cad][cad-mesh]") {
  meshIdfPart(2);
}

TEST_CASE("cad mesh: the shapes built with OCCT are closed and within δ", "[cad][cad-mesh]") {
  Backend backend = makeMirrorBackend();
  ModelFigures all;
  for (const auto& named : test::occtTestShapes())
    meshModel(CadFile{named.name, named.shape, {}}, named.name, backend, all);
  WARN("OCCT-built shapes: " << all.models << " (" << all.closedModels << " closed), "
                             << all.triangles << " triangles; largest distance/δ "
                             << all.worstOverDelta << " (" << all.worstModel << ")");
}
#endif
