// CAD import (issue 17, docs/cad.md): STEP/IGES/BRep → TrimmedModel, checked against OCCT.
#ifdef TESSERA_HAVE_CAD
#include <catch2/catch.hpp>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <TopLoc_Location.hxx>
#include <gp_Ax1.hxx>
#include <gp_Trsf.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "bspline/to_bezier.h"
#include "cad/cad_file.h"
#include "cad/face_surface.h"
#include "cad/to_trimmed.h"
#include "cad_test_shapes.h"
#include "scratch_dir.h"
#include "tessera/errors.h"
#include "trim/face_surface.h"
#include "trim/trim_classifier.h"

using namespace tessera;

namespace {

const char* kIdfLibrary = "/usr/share/freecad/Mod/Idf/Idflibs";

struct ImportFigures {
  size_t faces = 0, edges = 0, points = 0, failures = 0, loopsReversed = 0;
  double pieceGap = 0.0;  // pieces vs the OCCT surface, at the same face parameters
  double loopGap = 0.0;   // loop uv through the pieces vs the shared point
  double overhang = 0.0;  // loop uv beyond the pieces' domain, a share of the domain's extent
  size_t loopOutside = 0; // loop points farther than their OCCT tolerance (+ 1e-6 of the size)...
  size_t loopUnwarned = 0;  // ...and of those, the ones no CadEdgeWarning told of
  size_t warnings = 0, zeroArea = 0;
  double chord = 0.0;     // the edges' measured chord deviation
  double delta = 0.0;
};

double diagonal(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  return std::sqrt(box.SquareExtent());
}

double signedArea(const std::vector<glm::dvec2>& uv) {
  double twice = 0.0;
  for (size_t k = 0; k < uv.size(); ++k)
    twice += uv[k].x * uv[(k + 1) % uv.size()].y - uv[k].y * uv[(k + 1) % uv.size()].x;
  return 0.5 * twice;
}

using IdPair = std::pair<uint32_t, uint32_t>;
IdPair unordered(uint32_t a, uint32_t b) { return {std::min(a, b), std::max(a, b)}; }

// Everything the import promises, checked against OCCT's own answers; returns the figures.
// The import numbers faces, edges and vertices in one walk of the shape: the order, and the
// orientation and location each map keeps, must be TopExp::MapShapes's (face and edge indices
// are the file's face and edge numbers in every message and in the outputs).
void checkMapsAsTopExp(const CadImport& in, const TopoDS_Shape& shape) {
  const std::pair<TopAbs_ShapeEnum, const TopTools_IndexedMapOfShape*> maps[] = {
      {TopAbs_FACE, &in.faces}, {TopAbs_EDGE, &in.edges}, {TopAbs_VERTEX, &in.vertices}};
  for (const auto& [type, map] : maps) {
    TopTools_IndexedMapOfShape expected;
    TopExp::MapShapes(shape, type, expected);
    REQUIRE(map->Extent() == expected.Extent());
    int mismatched = 0;
    for (int k = 1; k <= expected.Extent(); ++k)
      if (!(*map)(k).IsEqual(expected(k))) ++mismatched;
    CHECK(mismatched == 0);
  }
}

ImportFigures checkImport(const CadFile& file) {
  const double size = diagonal(file.shape);
  const double delta = defaultCadTolerance(file.shape);
  const CadImport in = toTrimmedModel(file, delta);
  checkMapsAsTopExp(in, file.shape);
  ImportFigures figures;
  figures.delta = delta;
  figures.faces = in.faces.Extent();
  figures.edges = in.edges.Extent();
  figures.points = in.model.sharedPoints.size();
  figures.failures = in.failures.size();
  figures.loopsReversed = in.loopsReversed;
  figures.chord = in.maxChordDeviation;
  // Every face converts but zero-area slivers (wires back and forth along one curve), which are
  // empty faces, not failures: nothing to mesh, each named.
  std::set<uint32_t> failed;
  for (const auto& failure : in.failures) {
    std::printf("  failed: %s\n", failure.message.c_str());
    failed.insert(failure.faceIndex);
  }
  CHECK(in.failures.empty());
  for (const auto& empty : in.emptyFaces) {
    std::printf("  empty: %s\n", empty.message.c_str());
    failed.insert(empty.faceIndex);
    CHECK(empty.reason.rfind("zero-area face", 0) == 0);
    CHECK(empty.message.find(file.path + ": face " + std::to_string(empty.faceIndex)) == 0);
  }
  figures.zeroArea = in.emptyFaces.size();
  figures.warnings = in.warnings.size();
  std::set<std::pair<uint32_t, uint32_t>> warnedPoints;  // (face, point id) on a warned edge
  for (const auto& warning : in.warnings) {
    std::printf("  warning: %s\n", warning.message.c_str());
    for (size_t k = 0; k < in.edgeSamples[warning.edgeIndex].params.size(); ++k)
      warnedPoints.insert({warning.faceIndex, in.edgeSamples[warning.edgeIndex].pointId(k)});
  }
  CHECK(in.model.faces.size() + in.failures.size() + in.emptyFaces.size() ==
        static_cast<size_t>(in.faces.Extent()));
  CHECK(in.maxChordDeviation <= delta);

  // Segments of the edges' samples: each loop step must be one of them (closed loops of edges).
  std::set<IdPair> edgeSegments;
  for (const auto& samples : in.edgeSamples)
    for (size_t k = 0; k + 1 < samples.params.size(); ++k)
      edgeSegments.insert(unordered(samples.pointId(k), samples.pointId(k + 1)));
  std::map<IdPair, std::set<uint32_t>> facesOfSegment;

  for (size_t f = 0; f < in.model.faces.size(); ++f) {
    const TrimmedFace& face = in.model.faces[f];
    const TopoDS_Face source = TopoDS::Face(in.faces(static_cast<int>(face.faceIndex) + 1));
    CHECK(face.reversed == (source.Orientation() == TopAbs_REVERSED));
    // Pieces against OCCT's surface at a grid of the face's own (u, v), through the import's
    // own conversion (the same bounds give the same pieces and the same map).
    const std::array<double, 4>& b = in.uvBounds[f];
    const CadSurface surface = convertFaceSurface(
        faceBasisSurface(TopoDS::Face(source.Oriented(TopAbs_FORWARD))), b[0], b[1], b[2], b[3]);
    // The pieces' domain (a plane keeps no NURBS; another surface's NURBS spans its pieces).
    double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
    for (const BezierPatchPiece& piece : surface.pieces)
      u0 = std::min(u0, piece.u0), u1 = std::max(u1, piece.u1), v0 = std::min(v0, piece.v0),
      v1 = std::max(v1, piece.v1);
    for (int i = 0; i <= 4; ++i)
      for (int j = 0; j <= 4; ++j) {
        const gp_Pnt2d uv(u0 + (u1 - u0) * i / 4.0, v0 + (v1 - v0) * j / 4.0);
        const gp_Pnt p = surface.original->Value(uv.X(), uv.Y());
        figures.pieceGap = std::max(figures.pieceGap,
            glm::length(piecesPoint(face.pieces, surface.mapUv(uv)) - glm::dvec3(p.X(), p.Y(), p.Z())));
      }
    // mapUvs (the import's, one solve per distinct coordinate) is mapUv point by point; the
    // grid repeats every u and every v, and −0 is not +0.
    std::vector<gp_Pnt2d> grid{gp_Pnt2d(-0.0, v0), gp_Pnt2d(0.0, v1)};
    for (int i = 0; i <= 4; ++i)
      for (int j = 0; j <= 4; ++j) grid.emplace_back(u0 + (u1 - u0) * i / 4.0, v0 + (v1 - v0) * j / 4.0);
    const std::vector<glm::dvec2> mapped = surface.mapUvs(grid);
    REQUIRE(mapped.size() == grid.size());
    size_t mapDiffers = 0;
    for (size_t k = 0; k < grid.size(); ++k) {
      const glm::dvec2 one = surface.mapUv(grid[k]);
      if (std::memcmp(&one, &mapped[k], sizeof one) != 0) ++mapDiffers;
    }
    CHECK(mapDiffers == 0);
    // Loops: closed chains of edge segments, outer counter-clockwise, holes clockwise, every
    // point's uv on the pieces at its shared point (within the OCCT tolerance of its edge).
    // Every loop point within the pieces' domain: a face cut at the wrong place of a periodic
    // NURBS once left a sliver of its loops outside (0.031 rad of 2π, 5·10⁻³, on RLF_7030's face
    // 0), where the pieces were only extrapolated. Pcurves may overhang a surface's own bounds
    // by the file's tolerance (5·10⁻⁶ of the extent on CAP_50SGV_8_10's B-spline face 18).
    glm::dvec2 lo(face.pieces[0].u0, face.pieces[0].v0), hi = lo;
    for (const BezierPatchPiece& p : face.pieces)
      lo = glm::min(lo, {p.u0, p.v0}), hi = glm::max(hi, {p.u1, p.v1});
    for (const TrimLoop& loop : face.loops)
      for (const glm::dvec2& uv : loop.uv) {
        const glm::dvec2 beyond = glm::max(lo - uv, uv - hi) / (hi - lo);
        figures.overhang = std::max({figures.overhang, beyond.x, beyond.y});
      }
    size_t outer = 0;
    for (size_t k = 1; k < face.loops.size(); ++k)
      if (std::abs(signedArea(face.loops[k].uv)) > std::abs(signedArea(face.loops[outer].uv))) outer = k;
    for (size_t k = 0; k < face.loops.size(); ++k) {
      const TrimLoop& loop = face.loops[k];
      REQUIRE(loop.uv.size() == loop.pointIds.size());
      CHECK((signedArea(loop.uv) > 0.0) == (k == outer));
      for (size_t p = 0; p < loop.uv.size(); ++p) {
        const uint32_t a = loop.pointIds[p], b = loop.pointIds[(p + 1) % loop.uv.size()];
        const IdPair segment = unordered(a, b);
        if (!edgeSegments.count(segment)) {
          UNSCOPED_INFO(face.label << ": loop step " << a << " → " << b << " is no edge segment");
          CHECK(edgeSegments.count(segment) == 1);
        }
        facesOfSegment[segment].insert(face.faceIndex);
        const double gap = glm::length(piecesPoint(face.pieces, loop.uv[p]) - in.model.sharedPoints[a]);
        figures.loopGap = std::max(figures.loopGap, gap);
        if (gap > in.pointTolerances[a] + 1e-6 * size) {
          ++figures.loopOutside;
          if (!warnedPoints.count({face.faceIndex, a})) ++figures.loopUnwarned;
        }
      }
    }
  }
  CHECK(figures.pieceGap <= 1e-9 * size);
  CHECK(figures.overhang <= 1e-4);
  CHECK(figures.loopUnwarned == 0);

  // Each non-degenerate edge's first segment is used by exactly the faces OCCT says use it.
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(file.shape, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  size_t mismatched = 0;
  for (int e = 1; e <= in.edges.Extent(); ++e) {
    const EdgeSamples& samples = in.edgeSamples[static_cast<size_t>(e - 1)];
    if (samples.degenerated) continue;
    std::set<uint32_t> expected;
    if (edgeFaces.Contains(in.edges(e)))
      for (const auto& f : edgeFaces.FindFromKey(in.edges(e)))
        if (!failed.count(static_cast<uint32_t>(in.faces.FindIndex(f) - 1)))
          expected.insert(static_cast<uint32_t>(in.faces.FindIndex(f) - 1));
    const IdPair first = unordered(samples.pointId(0), samples.pointId(1));
    const std::set<uint32_t> used = facesOfSegment.count(first) ? facesOfSegment.at(first) : std::set<uint32_t>{};
    if (used != expected) ++mismatched;
  }
  CHECK(mismatched == 0);
  // The GPU trim classification's packing (trim/trim_classifier.h) takes the model as it is.
  CHECK_NOTHROW(packTrimSet(in.model));
  return figures;
}

void printFigures(const std::string& name, const ImportFigures& f, double ms) {
  std::printf(
      "cad import %-30s faces %4zu  edges %4zu  points %6zu  failed %zu  zero-area %zu  "
      "reversed loops %zu  δ %.3g  chord %.3g  piece gap %.2e  loop gap %.2e (%zu beyond "
      "tolerance, %zu edge warnings)  overhang %.1e  %.0f ms\n",
      name.c_str(), f.faces, f.edges, f.points, f.failures, f.zeroArea, f.loopsReversed, f.delta,
      f.chord, f.pieceGap, f.loopGap, f.loopOutside, f.warnings, f.overhang, ms);
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

std::vector<std::string> idfFiles() {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(kIdfLibrary)) {
    const std::string ext = entry.path().extension().string();
    if (ext == ".stp" || ext == ".igs") files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("cad: shapes built with OCCT convert face by face, exactly and watertight", "[cad]") {
  for (const auto& named : test::occtTestShapes()) {
    INFO(named.name);
    const auto start = std::chrono::steady_clock::now();
    const ImportFigures figures = checkImport(CadFile{named.name, named.shape, {}});
    printFigures(named.name, figures, millisecondsSince(start));
    CHECK(figures.faces > 0);
  }
}

// The library in three interleaved parts (files k, k + 3, ...): three CTest tests that run side
// by side, since reading STEP is most of the time.
void importIdfPart(size_t part) {
  const std::vector<std::string> files = idfFiles();
  REQUIRE(files.size() == 32);  // Debian's freecad-common (scripts/deps.sh installs it)
  ImportFigures total;
  size_t count = 0;
  const auto all = std::chrono::steady_clock::now();
  for (size_t k = part; k < files.size(); k += 3, ++count) {
    const std::string& path = files[k];
    INFO(path);
    const auto start = std::chrono::steady_clock::now();
    const ImportFigures f = checkImport(readCadFile(path));
    printFigures(std::filesystem::path(path).filename().string(), f, millisecondsSince(start));
    total.faces += f.faces, total.edges += f.edges, total.points += f.points;
    total.failures += f.failures, total.loopsReversed += f.loopsReversed, total.loopOutside += f.loopOutside;
    total.warnings += f.warnings, total.zeroArea += f.zeroArea;
    total.pieceGap = std::max(total.pieceGap, f.pieceGap), total.loopGap = std::max(total.loopGap, f.loopGap);
    total.chord = std::max(total.chord, f.chord);
    total.overhang = std::max(total.overhang, f.overhang);
  }
  printFigures("IDF part " + std::to_string(part + 1) + "/3 (" + std::to_string(count) + " files)", total,
               millisecondsSince(all));
}

TEST_CASE("cad: FreeCAD's IDF library imports with every face converted (part 1 of 3)", "[cad]") { importIdfPart(0); }
TEST_CASE("cad: FreeCAD's IDF library imports with every face converted (part 2 of 3)", "[cad]") { importIdfPart(1); }
TEST_CASE("cad: FreeCAD's IDF library imports with every face converted (part 3 of 3)", "[cad]") { importIdfPart(2); }

TEST_CASE("cad: an assembly gives every instance at its place", "[cad]") {
  const std::string dir = kIdfLibrary;
  REQUIRE(std::filesystem::exists(dir + "/I22_2_5_16withEPL22_6_16.stp"));  // freecad-common
  const CadFile both = readCadFile(dir + "/I22_2_5_16withEPL22_6_16.stp");
  const CadFile first = readCadFile(dir + "/I22_2_5_16.stp");
  const CadFile second = readCadFile(dir + "/EPL22_6_16.stp");
  TopTools_IndexedMapOfShape f0, f1, f2, solids;
  TopExp::MapShapes(both.shape, TopAbs_FACE, f0);
  TopExp::MapShapes(first.shape, TopAbs_FACE, f1);
  TopExp::MapShapes(second.shape, TopAbs_FACE, f2);
  TopExp::MapShapes(both.shape, TopAbs_SOLID, solids);
  std::printf("cad assembly: %d faces = %d + %d, %d solids, diagonals %.3f vs %.3f and %.3f\n",
              f0.Extent(), f1.Extent(), f2.Extent(), solids.Extent(), diagonal(both.shape),
              diagonal(first.shape), diagonal(second.shape));
  CHECK(f0.Extent() == f1.Extent() + f2.Extent());
  REQUIRE(solids.Extent() >= 2);
  // The instances are placed apart: their boxes differ, and the whole is larger than either.
  Bnd_Box a, b;
  BRepBndLib::Add(solids(1), a);
  BRepBndLib::Add(solids(solids.Extent()), b);
  CHECK(a.CornerMin().Distance(b.CornerMin()) + a.CornerMax().Distance(b.CornerMax()) > 1e-3);
  CHECK(diagonal(both.shape) > std::max(diagonal(first.shape), diagonal(second.shape)) - 1e-9);
  const CadImport in = toTrimmedModel(both, defaultCadTolerance(both.shape));
  CHECK(in.failures.empty());
  CHECK(in.model.faces.size() == static_cast<size_t>(f0.Extent()));
}

TEST_CASE("cad: face labels carry the STEP entity", "[cad]") {
  const std::string path = std::string(kIdfLibrary) + "/SOT23.stp";
  if (!std::filesystem::exists(path)) return;
  const CadImport in = toTrimmedModel(readCadFile(path), 0.01);
  REQUIRE(!in.model.faces.empty());
  std::printf("cad label: %s\n", in.model.faces.front().label.c_str());
  CHECK(in.model.faces.front().label.rfind("face 0 (#", 0) == 0);
  CHECK(in.model.faces.front().label.find("FACE)") != std::string::npos);
}

TEST_CASE("cad: unreadable files are refused naming the file", "[cad]") {
  test::ScratchDir dir("cad");
  const std::string garbage = (dir.path / "garbage.step").string();
  std::ofstream(garbage) << "this is not ISO-10303-21\n";
  const std::string unknown = (dir.path / "model.xyz").string();
  std::ofstream(unknown) << "x";
  const std::string missing = (dir.path / "missing.igs").string();
  for (const std::string& path : {garbage, unknown, missing}) {
    INFO(path);
    try {
      readCadFile(path);
      FAIL("no error");
    } catch (const InputError& e) {
      std::printf("cad refused: %s\n", e.what());
      CHECK(e.file() == path);
      CHECK(std::string(e.what()).find(path) != std::string::npos);
    }
  }
}

TEST_CASE("cad: a .BREP file reads whatever the extension's case", "[cad]") {
  test::ScratchDir dir("cad");
  const std::string path = (dir.path / "box.BREP").string();
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(1.0, 2.0, 3.0).Shape();
  REQUIRE(BRepTools::Write(box, path.c_str()));
  const CadFile file = readCadFile(path);
  const CadImport in = toTrimmedModel(file, 0.01);
  CHECK(in.model.faces.size() == 6);
  CHECK(in.failures.empty());
  CHECK(in.model.sharedPoints.size() == 8);  // a box's edges are straight: vertices only
}

TEST_CASE("cad: a face that fails is reported, the others kept", "[cad]") {
  TopoDS_Compound both;
  BRep_Builder builder;
  builder.MakeCompound(both);
  builder.Add(both, test::degreeEightFace());
  builder.Add(both, BRepPrimAPI_MakeBox(1.0, 1.0, 1.0).Shape());
  const CadImport in = toTrimmedModel(CadFile{"compound.step", both, {}}, 0.01);
  REQUIRE(in.failures.size() == 1);
  std::printf("cad failure: %s\n", in.failures[0].message.c_str());
  CHECK(in.failures[0].faceIndex == 0);
  CHECK(in.failures[0].message.find("compound.step: face 0: ") == 0);
  CHECK(in.failures[0].reason.find("above 7") != std::string::npos);
  CHECK(in.model.faces.size() == 6);
  CHECK_THROWS_AS(toTrimmedModel(CadFile{"x", both, {}}, 0.0), ArgumentError);
}
#endif

TEST_CASE("cad: FaceSurface::pointsAlongU gives point()'s doubles on the IDF library's faces",
          "[cad]") {
  // meanScales takes its u-neighbours from pointsAlongU, which shares the v direction's sums:
  // bit for bit the three point() calls, on every kind of piece (planes, cylinders, rational
  // tori, B-splines of several pieces), at piece sides and across them (three calls there).
  const std::vector<std::string> files = idfFiles();
  REQUIRE(files.size() == 32);
  size_t compared = 0, multiPiece = 0, rational = 0;
  for (size_t k = 0; k < files.size(); k += 4) {
    INFO(files[k]);
    const CadFile file = readCadFile(files[k]);
    const CadImport in = toTrimmedModel(file, defaultCadTolerance(file.shape));
    for (const TrimmedFace& face : in.model.faces) {
      const tessera::FaceSurface surface(face);
      multiPiece += face.pieces.size() > 1;
      for (const BezierPatchPiece& p : face.pieces) rational += !p.patch.weights.empty();
      for (const BezierPatchPiece& p : face.pieces)
        for (int i = 0; i <= 4; ++i)
          for (int j = 0; j <= 4; ++j) {
            const glm::dvec2 uv(p.u0 + (p.u1 - p.u0) * i / 4.0, p.v0 + (p.v1 - p.v0) * j / 4.0);
            for (const double h : {1e-3 * (p.u1 - p.u0), 0.6 * (p.u1 - p.u0)}) {
              const glm::dvec2 du(h, 0);
              const std::array<glm::dvec3, 3> along = surface.pointsAlongU({uv - du, uv, uv + du});
              REQUIRE(along[0] == surface.point(uv - du));
              REQUIRE(along[1] == surface.point(uv));
              REQUIRE(along[2] == surface.point(uv + du));
              ++compared;
            }
          }
    }
  }
  CHECK(compared > 10000);
  CHECK(multiPiece > 0);
  CHECK(rational > 0);
}

TEST_CASE("cad: FaceSurface::points gives point()'s doubles on the IDF library's faces", "[cad]") {
  // The refinement's samples and meanScales' points along v come from points(), which looks the
  // piece's form and degrees up once when every uv falls in one piece: bit for bit point() one
  // by one, within a piece (that loop) and across pieces (point() itself), -0 kept apart.
  const std::vector<std::string> files = idfFiles();
  REQUIRE(files.size() == 32);
  size_t compared = 0, onePieceLoops = 0, mixed = 0;
  for (size_t k = 1; k < files.size(); k += 4) {
    INFO(files[k]);
    const CadFile file = readCadFile(files[k]);
    const CadImport in = toTrimmedModel(file, defaultCadTolerance(file.shape));
    for (const TrimmedFace& face : in.model.faces) {
      const tessera::FaceSurface surface(face);
      std::vector<glm::dvec2> across;  // one uv of every piece: several pieces at once
      for (const BezierPatchPiece& p : face.pieces) {
        std::vector<glm::dvec2> uvs;
        for (int i = 0; i <= 4; ++i)
          for (int j = 0; j <= 4; ++j)
            uvs.emplace_back(p.u0 + (p.u1 - p.u0) * i / 4.0, p.v0 + (p.v1 - p.v0) * j / 4.0);
        across.push_back(0.5 * glm::dvec2(p.u0 + p.u1, p.v0 + p.v1));
        for (const std::vector<glm::dvec2>* set : {&uvs, &across}) {
          std::vector<glm::dvec3> batch(set->size());
          surface.points(set->data(), set->size(), batch.data());
          for (size_t s = 0; s < set->size(); ++s) {
            const glm::dvec3 one = surface.point((*set)[s]);
            REQUIRE(std::memcmp(&one, &batch[s], sizeof one) == 0);
            ++compared;
          }
          (set == &uvs ? onePieceLoops : mixed) += 1;
        }
      }
    }
  }
  CHECK(compared > 10000);
  CHECK(onePieceLoops > 100);
  CHECK(mixed > 100);
}

TEST_CASE("cad: FaceSurface::meanScales gives the pointwise version's doubles on the IDF faces",
          "[cad]") {
  // meanScales takes a one-piece face's grid with the rows in v shared by its columns; the
  // gap's metric (mesher.cpp) depends on its bits, so they must be meanScalesPointwise's, on the
  // face's box and on boxes past the piece (clamped) or inside it, -0 kept apart.
  const std::vector<std::string> files = idfFiles();
  REQUIRE(files.size() == 32);
  size_t compared = 0, onePiece = 0, rational = 0;
  const auto same = [](const tessera::FaceSurface::Scales& a, const tessera::FaceSurface::Scales& b) {
    return std::memcmp(&a.speeds, &b.speeds, sizeof a.speeds) == 0 &&
           std::memcmp(&a.bending, &b.bending, sizeof a.bending) == 0;
  };
  for (size_t k = 3; k < files.size(); k += 4) {
    INFO(files[k]);
    const CadFile file = readCadFile(files[k]);
    const CadImport in = toTrimmedModel(file, defaultCadTolerance(file.shape));
    for (const TrimmedFace& face : in.model.faces) {
      const tessera::FaceSurface surface(face);
      glm::dvec2 lo(face.pieces[0].u0, face.pieces[0].v0), hi = lo;
      for (const BezierPatchPiece& p : face.pieces)
        lo = glm::min(lo, {p.u0, p.v0}), hi = glm::max(hi, {p.u1, p.v1});
      const glm::dvec2 extent = hi - lo;
      for (const auto& [a, b] : {std::pair(lo, hi), std::pair(lo - 0.3 * extent, hi + 0.1 * extent),
                                 std::pair(lo + 0.2 * extent, hi - 0.4 * extent)}) {
        REQUIRE(same(surface.meanScales(a, b), surface.meanScalesPointwise(a, b)));
        ++compared;
      }
      onePiece += face.pieces.size() == 1;
      rational += !face.pieces[0].patch.weights.empty();
    }
  }
  CHECK(compared > 300);
  CHECK(onePiece > 100);
  CHECK(rational > 10);
}

TEST_CASE("cad: a plane's NURBS and piece are GeomConvert's and the knot insertion's, bit for bit",
          "[cad]") {
  // convertFaceSurface builds a plane's bilinear NURBS and its one piece directly; the path it
  // replaces, GeomConvert on the trimmed plane and the knot insertion, must give the same bits.
  const std::vector<std::string> files = idfFiles();
  REQUIRE(files.size() == 32);
  size_t planes = 0;
  for (size_t k = 2; k < files.size(); k += 4) {
    INFO(files[k]);
    const CadFile file = readCadFile(files[k]);
    const CadImport in = toTrimmedModel(file, defaultCadTolerance(file.shape));
    for (size_t f = 0; f < in.model.faces.size(); ++f) {
      const TopoDS_Face face = TopoDS::Face(
          in.faces(int(in.model.faces[f].faceIndex) + 1).Oriented(TopAbs_FORWARD));
      const Handle(Geom_Surface) basis = faceBasisSurface(face);
      if (!basis->IsKind(STANDARD_TYPE(Geom_Plane))) continue;
      const std::array<double, 4>& b = in.uvBounds[f];
      const CadSurface direct = convertFaceSurface(basis, b[0], b[1], b[2], b[3]);
      const Handle(Geom_BSplineSurface) converted = GeomConvert::SurfaceToBSplineSurface(
          new Geom_RectangularTrimmedSurface(basis, b[0], b[1], b[2], b[3]));
      CHECK(direct.nurbs.IsNull());  // a plane keeps only its piece, GeomConvert's net
      REQUIRE(converted->UDegree() == 1);
      REQUIRE(converted->VDegree() == 1);
      REQUIRE_FALSE((converted->IsURational() || converted->IsVRational()));
      BSplineSurface net;
      net.degreeU = converted->UDegree(), net.degreeV = converted->VDegree();
      net.countU = converted->NbUPoles(), net.countV = converted->NbVPoles();
      for (int i = 1; i <= net.countU + net.degreeU + 1; ++i) net.knotsU.push_back(converted->UKnotSequence()(i));
      for (int j = 1; j <= net.countV + net.degreeV + 1; ++j) net.knotsV.push_back(converted->VKnotSequence()(j));
      for (int i = 1; i <= net.countU; ++i)
        for (int j = 1; j <= net.countV; ++j) {
          const gp_Pnt p = converted->Pole(i, j);
          net.cp.push_back(glm::dvec3(p.X(), p.Y(), p.Z()) * 1.0);
        }
      const std::vector<BezierPatchPiece> inserted = bezierPatches(net);
      REQUIRE(inserted.size() == 1);
      REQUIRE(direct.pieces.size() == 1);
      const BezierPatchPiece &x = inserted[0], &y = direct.pieces[0];
      CHECK((x.u0 == y.u0 && x.u1 == y.u1 && x.v0 == y.v0 && x.v1 == y.v1));
      REQUIRE(x.patch.cp.size() == y.patch.cp.size());
      REQUIRE(std::memcmp(x.patch.cp.data(), y.patch.cp.data(),
                          x.patch.cp.size() * sizeof(glm::dvec3)) == 0);
      CHECK(y.patch.weights.empty());
      CHECK_FALSE(direct.reparametrised);
      ++planes;
    }
  }
  CHECK(planes > 100);
}

namespace {

// The NURBS of two conversions, bit for bit: degrees, counts, knots, multiplicities, poles and
// weights.
void requireSameNurbs(const Handle(Geom_BSplineSurface)& a, const Handle(Geom_BSplineSurface)& b) {
  REQUIRE(a->UDegree() == b->UDegree());
  REQUIRE(a->VDegree() == b->VDegree());
  REQUIRE(a->NbUPoles() == b->NbUPoles());
  REQUIRE(a->NbVPoles() == b->NbVPoles());
  REQUIRE(a->NbUKnots() == b->NbUKnots());
  REQUIRE(a->NbVKnots() == b->NbVKnots());
  REQUIRE(a->IsURational() == b->IsURational());
  REQUIRE(a->IsVRational() == b->IsVRational());
  const auto sameBits = [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; };
  for (int k = 1; k <= a->NbUKnots(); ++k) {
    REQUIRE(sameBits(a->UKnot(k), b->UKnot(k)));
    REQUIRE(a->UMultiplicity(k) == b->UMultiplicity(k));
  }
  for (int k = 1; k <= a->NbVKnots(); ++k) {
    REQUIRE(sameBits(a->VKnot(k), b->VKnot(k)));
    REQUIRE(a->VMultiplicity(k) == b->VMultiplicity(k));
  }
  for (int i = 1; i <= a->NbUPoles(); ++i)
    for (int j = 1; j <= a->NbVPoles(); ++j) {
      const gp_Pnt p = a->Pole(i, j), q = b->Pole(i, j);
      REQUIRE(std::memcmp(&p, &q, sizeof p) == 0);
      REQUIRE(sameBits(a->Weight(i, j), b->Weight(i, j)));
    }
}

// Both routes of convertFaceSurface on every non-planar face of `in`, bit for bit: the same
// NURBS, map and pieces. Counts the faces by surface kind (and "whole u" where a face wraps its
// u period), and in `blocks` those whose NURBS needed no knot insertion.
void requireSameRoutes(const CadImport& in, std::map<std::string, size_t>& compared, size_t& blocks) {
  for (size_t f = 0; f < in.model.faces.size(); ++f) {
    INFO("face " << in.model.faces[f].faceIndex);
    const TopoDS_Face face = TopoDS::Face(
        in.faces(int(in.model.faces[f].faceIndex) + 1).Oriented(TopAbs_FORWARD));
    const Handle(Geom_Surface) basis = faceBasisSurface(face);
    if (basis->IsKind(STANDARD_TYPE(Geom_Plane))) continue;
    const std::array<double, 4>& b = in.uvBounds[f];
    const CadSurface direct = convertFaceSurface(basis, b[0], b[1], b[2], b[3]);
    const CadSurface reference =
        convertFaceSurface(basis, b[0], b[1], b[2], b[3], ConversionRoute::GeomConvert);
    requireSameNurbs(direct.nurbs, reference.nurbs);
    REQUIRE(direct.reparametrised == reference.reparametrised);
    REQUIRE(std::memcmp(&direct.uRef, &reference.uRef, sizeof direct.uRef) == 0);
    REQUIRE(std::memcmp(&direct.vRef, &reference.vRef, sizeof direct.vRef) == 0);
    REQUIRE(direct.pieces.size() == reference.pieces.size());
    for (size_t p = 0; p < direct.pieces.size(); ++p) {
      const BezierPatchPiece &x = direct.pieces[p], &y = reference.pieces[p];
      REQUIRE(std::memcmp(&x.u0, &y.u0, sizeof x.u0) == 0);
      REQUIRE(std::memcmp(&x.u1, &y.u1, sizeof x.u1) == 0);
      REQUIRE(std::memcmp(&x.v0, &y.v0, sizeof x.v0) == 0);
      REQUIRE(std::memcmp(&x.v1, &y.v1, sizeof x.v1) == 0);
      REQUIRE(x.patch.degreeU == y.patch.degreeU);
      REQUIRE(x.patch.degreeV == y.patch.degreeV);
      REQUIRE(x.patch.cp.size() == y.patch.cp.size());
      REQUIRE(std::memcmp(x.patch.cp.data(), y.patch.cp.data(),
                          x.patch.cp.size() * sizeof(glm::dvec3)) == 0);
      REQUIRE(x.patch.weights.size() == y.patch.weights.size());
      // Polynomial pieces have no weights: memcmp must not see their null data (UBSan).
      REQUIRE((x.patch.weights.empty() ||
               std::memcmp(x.patch.weights.data(), y.patch.weights.data(),
                           x.patch.weights.size() * sizeof(double)) == 0));
    }
    const std::string kind = basis->DynamicType()->Name();
    ++compared[kind];
    if (basis->IsUPeriodic() && b[1] - b[0] >= basis->UPeriod() * (1 - 1e-9))
      ++compared["whole u " + kind];
    // The blocks' case: a NURBS with no knot to insert (every conic's and line's).
    const Handle(Geom_BSplineSurface)& s = direct.nurbs;
    if (s->NbUPoles() == (s->NbUKnots() - 1) * s->UDegree() + 1 &&
        s->NbVPoles() == (s->NbVKnots() - 1) * s->VDegree() + 1)
      ++blocks;
  }
}

}  // namespace

TEST_CASE("cad: the direct conversions are GeomConvert's and the knot insertion's, bit for bit",
          "[cad]") {
  // convertFaceSurface's Direct route builds cylinders and cones from OCCT's Convert_ classes
  // and segments a copy of a non-periodic B-spline, without GeomConvert's trimmed copy, and cuts
  // a NURBS whose knots need no insertion into its blocks; the GeomConvert route takes
  // GeomConvert and the insertion for every surface. Every face but the planes (their own test
  // above) of the whole library, both routes: the same NURBS, map and pieces, bit for bit.
  const std::vector<std::string> files = idfFiles();
  REQUIRE(files.size() == 32);
  std::map<std::string, size_t> compared;
  size_t blocks = 0;
  for (const std::string& path : files) {
    INFO(path);
    const CadFile file = readCadFile(path);
    requireSameRoutes(toTrimmedModel(file, defaultCadTolerance(file.shape)), compared, blocks);
  }
  for (const auto& [kind, count] : compared) UNSCOPED_INFO(kind << ": " << count);
  CHECK(compared["Geom_CylindricalSurface"] > 200);
  CHECK(compared["whole u Geom_CylindricalSurface"] >= 4);
  CHECK(compared["Geom_ConicalSurface"] > 10);
  CHECK(blocks > 300);
}

TEST_CASE("cad: the direct conversions match GeomConvert on whole and partial cones and cylinders",
          "[cad]") {
  // The library has no cone that wraps its period: OCCT's solids of revolution, whole and cut
  // to an angle, moved off the origin and turned (located faces), and the other test shapes.
  gp_Trsf moved;
  moved.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 2, 3)), 0.7);
  moved.SetTranslationPart(gp_Vec(3.0, -1.5, 20.0));
  std::vector<test::NamedShape> shapes = test::occtTestShapes();
  shapes.push_back({"cone", BRepPrimAPI_MakeCone(1.0, 0.4, 2.0).Shape()});
  shapes.push_back({"cone, 100°", BRepPrimAPI_MakeCone(1.0, 0.4, 2.0, 100.0 * M_PI / 180.0).Shape()});
  shapes.push_back({"cylinder, 250°", BRepPrimAPI_MakeCylinder(0.7, 1.5, 250.0 * M_PI / 180.0).Shape()});
  shapes.push_back({"cone, moved", BRepPrimAPI_MakeCone(1.0, 0.4, 2.0).Shape().Moved(TopLoc_Location(moved))});
  shapes.push_back({"cone, 200°, moved",
                    BRepPrimAPI_MakeCone(0.3, 1.1, 0.8, 200.0 * M_PI / 180.0).Shape().Moved(TopLoc_Location(moved))});
  shapes.push_back({"cylinder, 30°, moved",
                    BRepPrimAPI_MakeCylinder(0.7, 1.5, 30.0 * M_PI / 180.0).Shape().Moved(TopLoc_Location(moved))});
  std::map<std::string, size_t> compared;
  size_t blocks = 0;
  for (const test::NamedShape& named : shapes) {
    INFO(named.name);
    requireSameRoutes(toTrimmedModel(CadFile{named.name, named.shape, {}}, 0.01), compared, blocks);
  }
  for (const auto& [kind, count] : compared) UNSCOPED_INFO(kind << ": " << count);
  CHECK(compared["whole u Geom_ConicalSurface"] >= 2);
  CHECK(compared["Geom_ConicalSurface"] >= 4);  // two whole, two cut to an angle
  CHECK(compared["whole u Geom_CylindricalSurface"] >= 1);
  CHECK(compared["Geom_CylindricalSurface"] >= 4);
  CHECK(blocks >= 8);
}

// Each edge's end points as discretiseEdge numbers them from TopExp::Vertices on the edge taken
// FORWARD (the import reads them off its walk where it can).
void checkEdgeEndsAsTopExp(const CadImport& in) {
  for (int e = 1; e <= in.edges.Extent(); ++e) {
    INFO("edge " << e);
    TopoDS_Vertex first, last;
    TopExp::Vertices(TopoDS::Edge(in.edges(e).Oriented(TopAbs_FORWARD)), first, last);
    const EdgeSamples& samples = in.edgeSamples[size_t(e - 1)];
    CHECK(samples.firstId == uint32_t(in.vertices.FindIndex(first) - 1));
    if (!samples.degenerated) CHECK(samples.lastId == uint32_t(in.vertices.FindIndex(last) - 1));
  }
}

// The maps are built two ways: the faces' part of the walk on all threads where the shape is
// faces under compounds, solids and shells, the serial walk where anything else hangs there
// (here a free edge and a free vertex between two boxes, one of them moved and reversed and
// one used twice). Both must number as TopExp::MapShapes does, and on any thread count alike.
TEST_CASE("cad: the shape maps are TopExp's with and without free edges and vertices", "[cad]") {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(1.0, 2.0, 3.0).Shape();
  gp_Trsf shift;
  shift.SetTranslation(gp_Vec(5.0, 0.0, 0.0));
  const TopoDS_Shape moved = box.Moved(TopLoc_Location(shift)).Reversed();
  const TopoDS_Shape other = BRepPrimAPI_MakeBox(gp_Pnt(0.0, 5.0, 0.0), 1.0, 1.0, 1.0).Shape();
  const TopoDS_Shape edge = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 9), gp_Pnt(1, 1, 9)).Shape();
  const TopoDS_Shape vertex = BRepBuilderAPI_MakeVertex(gp_Pnt(0, 0, 7)).Shape();
  for (const bool loose : {false, true}) {
    TopoDS_Compound all;
    BRep_Builder builder;
    builder.MakeCompound(all);
    builder.Add(all, moved);
    if (loose) builder.Add(all, edge), builder.Add(all, vertex);
    builder.Add(all, other);
    builder.Add(all, moved);  // met again: mapped once
    INFO("free edge and vertex: " << loose);
    for (const unsigned threads : {1u, 4u}) {
      const CadImport in = toTrimmedModel(CadFile{"boxes", all, {}}, 0.01, threads);
      checkMapsAsTopExp(in, all);
      checkEdgeEndsAsTopExp(in);
      CHECK(in.faces.Extent() == 12);
      CHECK(in.edges.Extent() == 24 + (loose ? 1 : 0));
      CHECK(in.vertices.Extent() == 16 + (loose ? 3 : 0));
      CHECK(in.failures.empty());
    }
  }
  // A cone's apex (a degenerated edge) and a cylinder's seams and closed circles, one reversed.
  TopoDS_Compound round;
  BRep_Builder builder;
  builder.MakeCompound(round);
  builder.Add(round, BRepPrimAPI_MakeCylinder(1.0, 2.0).Shape().Reversed());
  builder.Add(round, BRepPrimAPI_MakeCone(1.0, 0.0, 2.0).Shape());
  const CadImport in = toTrimmedModel(CadFile{"round", round, {}}, 0.01, 1);
  checkMapsAsTopExp(in, round);
  checkEdgeEndsAsTopExp(in);
  CHECK(in.failures.empty());
}
