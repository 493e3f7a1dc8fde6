// An assembly's repeated parts (host/cad/instances.h, docs/cad.md "Assemblies"): a part placed
// several times is converted and meshed once and its mesh moved to every other place. Each
// instance must still be closed, within δ of its own faces, and named by its own face numbers;
// a scaled instance, and a part that shares an edge with another, are meshed in place.
#include <catch2/catch.hpp>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Writer.hxx>
#include <TopoDS_Iterator.hxx>
#include <gp_Ax1.hxx>
#include <gp_Trsf.hxx>

#include <algorithm>
#include <glm/gtc/matrix_access.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cad/cad_file.h"
#include "cad/instances.h"
#include "cad/mesh_cad_file.h"
#include "cad/to_trimmed.h"
#include "cad_test_shapes.h"
#include "glb_reader.h"
#include "io/gltf_writer.h"
#include "common/memory_budget.h"
#include "mesh/tessellate.h"
#include "mesh_checks.h"
#include "scratch_dir.h"
#include "tessera/cad.h"
#include "tessera/errors.h"

using namespace tessera;

namespace {

TopLoc_Location translation(double x, double y, double z) {
  gp_Trsf t;
  t.SetTranslation(gp_Vec(x, y, z));
  return TopLoc_Location(t);
}

TopoDS_Compound compoundOf(const std::vector<TopoDS_Shape>& shapes) {
  BRep_Builder builder;
  TopoDS_Compound compound;
  builder.MakeCompound(compound);
  for (const TopoDS_Shape& shape : shapes) builder.Add(compound, shape);
  return compound;
}

std::string written(const test::ScratchDir& dir, const std::string& name,
                    const TopoDS_Shape& shape) {
  const std::string path = (dir.path / name).string();
  REQUIRE(BRepTools::Write(shape, path.c_str()));
  return path;
}

ToleranceSpec absolute(double delta) {
  ToleranceSpec spec;
  spec.value = delta;
  spec.relative = false;
  spec.text = std::to_string(delta);
  return spec;
}

// CAP_50SGV_8_10 placed three times (moved; turned and moved) with a box, first or second,
// written to `dir` as one .brep.
std::string threeCapsAndABox(const test::ScratchDir& dir, bool boxFirst) {
  const CadFile cap = readCadFile("/usr/share/freecad/Mod/Idf/Idflibs/CAP_50SGV_8_10.stp");
  gp_Trsf turn;
  turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 1.0);
  std::vector<TopoDS_Shape> shapes = {
      cap.shape, cap.shape.Moved(translation(30, 0, 0)),
      cap.shape.Moved(TopLoc_Location(translation(0, -30, 0).Transformation() * turn))};
  shapes.insert(shapes.begin() + (boxFirst ? 0 : 1),
                BRepPrimAPI_MakeBox(gp_Pnt(0, 30, 0), 1.0, 1.0, 1.0).Shape());
  return written(dir, "caps.brep", compoundOf(shapes));
}

// The model's face numbers of `leaf`'s faces (TopExp::MapShapes order, as the import numbers).
std::vector<uint32_t> faceNumbers(const TopoDS_Shape& model, const TopoDS_Shape& leaf) {
  TopTools_IndexedMapOfShape all, own;
  TopExp::MapShapes(model, TopAbs_FACE, all);
  TopExp::MapShapes(leaf, TopAbs_FACE, own);
  std::vector<uint32_t> numbers;
  for (int k = 1; k <= own.Extent(); ++k) numbers.push_back(uint32_t(all.FindIndex(own(k)) - 1));
  return numbers;
}

}  // namespace

TEST_CASE(
    "cad instances: a part placed three times is meshed once, each instance closed and "
    "within δ of its own faces",
    "[cad][instances]") {
  test::ScratchDir dir("cad_instances");
  const TopoDS_Shape part = BRepPrimAPI_MakeCylinder(1.0, 2.0).Shape();
  gp_Trsf turn;
  turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 1, 1)), 0.7);
  gp_Trsf turnedAndMoved = translation(0, 6, 1).Transformation();
  turnedAndMoved.Multiply(turn);
  gp_Trsf scaled;
  scaled.SetScale(gp_Pnt(10, 0, 0), 1.5);
  const std::vector<TopoDS_Shape> leaves = {
      part,
      BRepPrimAPI_MakeBox(gp_Pnt(-4, -4, 0), 1.0, 1.0, 1.0).Shape(),
      part.Moved(translation(5, 0, 0)),
      part.Moved(TopLoc_Location(turnedAndMoved)),
      part.Moved(TopLoc_Location(scaled), /*theRaiseExc=*/false),  // not rigid: in place
  };
  const std::string path = written(dir, "assembly.brep", compoundOf(leaves));
  const CadFile file = readCadFile(path);  // the shape as the run reads it (TShapes shared)

  constexpr double delta = 0.01;
  Backend backend = makeMirrorBackend();
  const CadMeshRun run = meshCadFile(path, absolute(delta), false, "", backend, nullptr);
  REQUIRE(run.failures.empty());
  CHECK(run.faces == 4 * 3 + 6);
  CHECK(run.instancedParts() == 1);
  CHECK(run.instanceCopies() == 2);
  Tessellator tessellator({Device::Cpu});  // the public API says so too
  CHECK(tessellateCadFile(tessellator, path).placements.size() == 2);
  REQUIRE(run.mesh.faces.size() == run.faces);
  REQUIRE(run.mesh.triangleFace.size() == run.mesh.mesh.triangleCount());

  // Closed, every instance: a copy welds to nothing but itself.
  const test::EdgeCensus census = test::censusOf(run.mesh.mesh, 0.0);
  CHECK(census.boundaryEdges == 0);
  CHECK(census.overusedEdges == 0);
  CHECK(census.inconsistentEdges == 0);
  CHECK(census.degenerateTriangles == 0);

  // Each face's triangles within δ of that face's own surface, at its own place: the copies'
  // motions and numbers measured against Open CASCADE, not against the stats they copied.
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(file.shape, TopAbs_FACE, faces);
  std::map<uint32_t, size_t> trianglesOf;
  double worstVertex = 0, worstInside = 0;
  const TriangleMesh& mesh = run.mesh.mesh;
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const uint32_t face = run.mesh.triangleFace[t];
    REQUIRE(face < uint32_t(faces.Extent()));
    ++trianglesOf[face];
    GeomAPI_ProjectPointOnSurf onSurface;
    onSurface.Init(BRep_Tool::Surface(TopoDS::Face(faces(int(face) + 1))), -1e9, 1e9, -1e9, 1e9);
    const auto distance = [&](const glm::dvec3& p) {
      onSurface.Perform(gp_Pnt(p.x, p.y, p.z));
      REQUIRE(onSurface.NbPoints() > 0);
      return onSurface.LowerDistance();
    };
    glm::dvec3 corner[3];
    for (int c = 0; c < 3; ++c) {
      corner[c] = glm::dvec3(mesh.positions[mesh.indices[3 * t + size_t(c)]]);
      worstVertex = std::max(worstVertex, distance(corner[c]));
    }
    for (const glm::dvec3& p :
         {(corner[0] + corner[1] + corner[2]) / 3.0, (corner[0] + corner[1]) / 2.0,
          (corner[1] + corner[2]) / 2.0, (corner[2] + corner[0]) / 2.0})
      worstInside = std::max(worstInside, distance(p));
  }
  INFO("vertices off their face by ≤ " << worstVertex << ", triangles by ≤ " << worstInside);
  CHECK(worstVertex <= 1e-5);  // fp32 positions
  CHECK(worstInside <= delta + 1e-5);
  CHECK(trianglesOf.size() == run.faces);  // every face has triangles, under its own number

  // The copies have the first instance's triangles, face by face (leaves as read back).
  std::vector<TopoDS_Shape> read;
  for (TopoDS_Iterator it(file.shape); it.More(); it.Next()) read.push_back(it.Value());
  REQUIRE(read.size() == leaves.size());
  const std::vector<uint32_t> first = faceNumbers(file.shape, read[0]);
  for (size_t leaf : {size_t(2), size_t(3)}) {
    const std::vector<uint32_t> copy = faceNumbers(file.shape, read[leaf]);
    REQUIRE(copy.size() == first.size());
    for (size_t f = 0; f < first.size(); ++f) {
      CHECK(trianglesOf[first[f]] > 0);
      CHECK(trianglesOf[copy[f]] == trianglesOf[first[f]]);
    }
  }
}

namespace {

// Every triangle a .glb draws, by face and centroid: each node's mesh, its primitives' indices
// into the shared POSITION accessor, moved by the node's matrix; a primitive's face plus the
// node's faceOffset.
std::multimap<uint32_t, glm::dvec3> drawnTriangles(const std::string& bytes) {
  using namespace test::glb;
  const Glb glb = parseGlb(bytes);
  const nlohmann::json& doc = glb.document;
  std::multimap<uint32_t, glm::dvec3> drawn;
  for (const nlohmann::json& node : doc.at("nodes")) {
    glm::dmat4 m(1.0);
    if (node.contains("matrix"))
      for (int k = 0; k < 16; ++k) m[k / 4][k % 4] = node["matrix"][k].get<double>();
    const int64_t offset =
        node.contains("extras") ? node["extras"]["faceOffset"].get<int64_t>() : 0;
    for (const nlohmann::json& p : doc.at("meshes").at(node["mesh"].get<int>()).at("primitives")) {
      const AccessorData positions = accessor(glb, p["attributes"]["POSITION"]);
      const AccessorData indices = accessor(glb, p["indices"]);
      const auto point = [&](size_t k) {
        const uint32_t v = indices.componentType == 5123 ? u16At(glb.bin, indices.offset + 2 * k)
                                                         : u32At(glb.bin, indices.offset + 4 * k);
        REQUIRE(v < positions.count);
        glm::dvec4 xyz(1.0);
        for (int c = 0; c < 3; ++c) xyz[c] = f32At(glb.bin, positions.offset + 12 * v + 4 * c);
        return glm::dvec3(m * xyz);
      };
      for (size_t k = 0; k < indices.count; k += 3)
        drawn.emplace(uint32_t(p["extras"]["face"].get<int64_t>() + offset),
                      (point(k) + point(k + 1) + point(k + 2)) / 3.0);
    }
  }
  return drawn;
}

}  // namespace

// The .glb draws the copies as nodes of their part's mesh: the same triangles, under the
// same faces, as the mesh with every copy (glTF-validated in test_gltf_writer's sample).
TEST_CASE("cad instances: the .glb draws each copy as a node, the same triangles",
          "[cad][instances]") {
  test::ScratchDir dir("cad_instances");
  const std::string path = threeCapsAndABox(dir, true);
  Backend backend = makeMirrorBackend();
  const CadMeshRun run = meshCadFile(path, ToleranceSpec{}, false, "", backend, nullptr);
  REQUIRE(run.glbInstances.placements.size() == 2);
  std::ostringstream instanced, flat;
  writeGlb(instanced, run.mesh.mesh, &run.mesh.triangleFace, &run.glbInstances);
  writeGlb(flat, run.mesh.mesh, &run.mesh.triangleFace);
  CHECK(instanced.str().size() * 2 < flat.str().size());
  const std::multimap<uint32_t, glm::dvec3> drawn = drawnTriangles(instanced.str());
  REQUIRE(drawn.size() == run.mesh.mesh.triangleCount());
  // Per face, each drawn centroid against the nearest of the flat mesh's, fp32 apart.
  std::multimap<uint32_t, glm::dvec3> expected;
  const TriangleMesh& m = run.mesh.mesh;
  for (size_t t = 0; t < m.triangleCount(); ++t)
    expected.emplace(run.mesh.triangleFace[t], (glm::dvec3(m.positions[m.indices[3 * t]]) +
                                                glm::dvec3(m.positions[m.indices[3 * t + 1]]) +
                                                glm::dvec3(m.positions[m.indices[3 * t + 2]])) /
                                                   3.0);
  double worst = 0;
  for (uint32_t face = 0; face < run.faces; ++face) {
    REQUIRE(drawn.count(face) == expected.count(face));
    for (auto [at, end] = drawn.equal_range(face); at != end; ++at) {
      double nearest = 1e300;
      for (auto [e, eEnd] = expected.equal_range(face); e != eEnd; ++e)
        nearest = std::min(nearest, glm::length(at->second - e->second));
      worst = std::max(worst, nearest);
    }
  }
  INFO("largest centroid difference " << worst);
  CHECK(worst < 1e-4);
}

namespace {

glm::dvec3 vertexOf(const Mesh& mesh, uint32_t v) {
  return {mesh.positions[3 * size_t(v)], mesh.positions[3 * size_t(v) + 1],
          mesh.positions[3 * size_t(v) + 2]};
}

}  // namespace

// CadOptions::expandInstances = false (include/tessera/cad.h): the mesh holds each part once,
// the placements say where else to draw it. Drawn that way, it is the expanded mesh: the same
// prefix, bit for bit, and each copy's triangles moved by its matrix under its face numbers.
TEST_CASE("cad instances: the API's instance view draws the expanded mesh",
          "[cad][instances][api]") {
  test::ScratchDir dir("cad_instances");
  const std::string path = threeCapsAndABox(dir, true);
  Tessellator tessellator({Device::Cpu});
  CadOptions options;
  const CadMesh expanded = tessellateCadFile(tessellator, path, options);
  options.expandInstances = false;
  const CadMesh listed = tessellateCadFile(tessellator, path, options);

  // The model's counts and measures, whichever view.
  CHECK(listed.faces == expanded.faces);
  CHECK(listed.facesMeshed == expanded.facesMeshed);
  CHECK(listed.tolerance == expanded.tolerance);
  CHECK(listed.maxDeviation == expanded.maxDeviation);
  CHECK(listed.maxParametricDeviation == expanded.maxParametricDeviation);
  CHECK(listed.warnings == expanded.warnings);
  REQUIRE(listed.parts.size() == 1);
  REQUIRE(listed.placements.size() == 2);
  REQUIRE(expanded.placements.size() == 2);

  // The listed mesh is the expanded one's beginning.
  const size_t vertices = listed.mesh.vertexCount(), triangles = listed.mesh.triangleCount();
  REQUIRE(0 < triangles);
  REQUIRE(expanded.mesh.triangleCount() > triangles);
  CHECK(std::equal(listed.mesh.positions.begin(), listed.mesh.positions.end(),
                   expanded.mesh.positions.begin()));
  CHECK(std::equal(listed.mesh.indices.begin(), listed.mesh.indices.end(),
                   expanded.mesh.indices.begin()));
  CHECK(std::equal(listed.triangleFaces.begin(), listed.triangleFaces.end(),
                   expanded.triangleFaces.begin()));

  // The part's ranges hold its faces' triangles and their vertices, and nothing else's.
  const CadPart& part = listed.parts[0];
  CHECK(3 * part.faceCount + 6 == listed.faces);  // three caps and a box
  const auto inPart = [&](uint32_t face) { return face - part.firstFace < part.faceCount; };
  for (uint32_t t = 0; t < triangles; ++t) {
    const bool mine = t - part.firstTriangle < part.triangleCount;
    REQUIRE(inPart(listed.triangleFaces[t]) == mine);
    for (int c = 0; c < 3; ++c)
      REQUIRE((listed.mesh.indices[3 * t + size_t(c)] - part.firstVertex < part.vertexCount) ==
              mine);
  }

  // Each placement: a rigid matrix; the part's triangles moved by it are the expanded mesh's
  // copy, in order after the prefix, its faces renumbered from the placement's first face.
  size_t next = triangles;
  for (const CadPlacement& placed : listed.placements) {
    REQUIRE(placed.part == 0);
    glm::dmat4 m;
    for (int k = 0; k < 16; ++k) m[k / 4][k % 4] = placed.matrix[size_t(k)];
    const glm::dmat3 turn(m);
    CHECK(glm::determinant(turn) > 0);
    const glm::dmat3 identity = glm::transpose(turn) * turn;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) CHECK(std::abs(identity[i][j] - (i == j)) < 1e-12);
    CHECK(glm::row(m, 3) == glm::dvec4(0, 0, 0, 1));
    double worst = 0;
    for (uint32_t k = 0; k < part.triangleCount; ++k, ++next) {
      const uint32_t t = part.firstTriangle + k;
      REQUIRE(expanded.triangleFaces[next] ==
              listed.triangleFaces[t] - part.firstFace + placed.firstFace);
      for (int c = 0; c < 3; ++c) {
        const glm::dvec3 moved = glm::dvec3(
            m * glm::dvec4(vertexOf(listed.mesh, listed.mesh.indices[3 * t + size_t(c)]), 1));
        worst = std::max(
            worst, glm::length(moved - vertexOf(expanded.mesh,
                                                expanded.mesh.indices[3 * next + size_t(c)])));
      }
    }
    INFO("largest distance, moved part to expanded copy: " << worst);
    CHECK(worst < 1e-5);  // fp32 positions, ~30 from the origin
  }
  CHECK(next == expanded.mesh.triangleCount());
  CHECK(expanded.mesh.vertexCount() ==
        vertices + listed.placements.size() * size_t(part.vertexCount));

  // The .glb of either is the same file (the CLI writes the expanded run's).
  Backend backend = makeMirrorBackend();
  const CadMeshRun all = meshCadFile(path, ToleranceSpec{}, false, "", backend, nullptr);
  const CadMeshRun once =
      meshCadFile(path, ToleranceSpec{}, false, "", backend, nullptr, 0, CopyPlacement::Listed);
  CHECK(once.mesh.faces.size() == all.mesh.faces.size());
  // The whole model's counts, which the CLI prints from a listed run (its .glb's).
  CHECK(once.modelTriangles() == all.mesh.mesh.triangleCount());
  CHECK(once.modelVertices() == all.mesh.mesh.vertexCount());
  CHECK(all.modelTriangles() == all.mesh.mesh.triangleCount());
  std::ostringstream fromAll, fromOnce;
  writeGlb(fromAll, all.mesh.mesh, &all.mesh.triangleFace, &all.glbInstances);
  writeGlb(fromOnce, once.mesh.mesh, &once.mesh.triangleFace, &once.glbInstances);
  CHECK(fromAll.str() == fromOnce.str());
}

TEST_CASE("cad instances: a part sharing an edge with another part is meshed at each place",
          "[cad][instances]") {
  test::ScratchDir dir("cad_instances");
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(1.0, 1.0, 1.0).Shape();
  TopTools_IndexedDataMapOfShapeListOfShape facesOfEdge;
  TopExp::MapShapesAndAncestors(box, TopAbs_EDGE, TopAbs_FACE, facesOfEdge);
  const TopoDS_Shape a = facesOfEdge(1).First(), b = facesOfEdge(1).Last();
  REQUIRE(!a.IsSame(b));
  // a and b welded along their edge; a placed again: it could not weld to b there, so it is
  // not a copy.
  const std::string path =
      written(dir, "faces.brep", compoundOf({a, b, a.Moved(translation(3, 0, 0))}));
  Backend backend = makeMirrorBackend();
  const CadMeshRun run = meshCadFile(path, absolute(0.01), false, "", backend, nullptr);
  CHECK(run.faces == 3);
  CHECK(run.instanceCopies() == 0);
  CHECK(run.mesh.mesh.triangleCount() == 6);  // planes: two triangles a face
  const test::EdgeCensus census = test::censusOf(run.mesh.mesh, 0.0);
  CHECK(census.boundaryEdges == 3 * 4 - 2);  // a and b share one side
}

// CAP_50SGV_8_10's two faces whose edge curves leave them (edge warnings): placed three times,
// with a part of its own between, the copies' warnings are those that converting every
// placement gives, face and edge numbers included, in the same order.
TEST_CASE("cad instances: the copies' warnings name the faces and edges every placement has",
          "[cad][instances]") {
  test::ScratchDir dir("cad_instances");
  const std::string path = threeCapsAndABox(dir, false);
  Backend backend = makeMirrorBackend();
  const CadMeshRun run = meshCadFile(path, ToleranceSpec{}, false, "", backend, nullptr);
  REQUIRE(run.instanceCopies() == 2);
  const CadFile file = readCadFile(path);
  const CadImport every = toTrimmedModel(file, run.delta);  // every placement converted
  REQUIRE(every.warnings.size() == 6);
  std::vector<std::string> expected;
  for (const CadEdgeWarning& w : every.warnings) expected.push_back(w.message);
  CHECK(run.warnings == expected);
  CHECK(run.faces == size_t(every.faces.Extent()));
  CHECK(run.edges == size_t(every.edges.Extent()));
}

// The copies multiply the mesh: they are counted against the memory budget before they are made.
TEST_CASE("cad instances: the copies are held to the memory budget", "[cad][instances]") {
  test::ScratchDir dir("cad_instances");
  const TopoDS_Shape part = BRepPrimAPI_MakeCylinder(1.0, 2.0).Shape();
  std::vector<TopoDS_Shape> placed;
  for (int k = 0; k < 40; ++k) placed.push_back(part.Moved(translation(3.0 * k, 0, 0)));
  const std::string path = written(dir, "forty.brep", compoundOf(placed));
  Backend backend = makeMirrorBackend();
  const CadMeshRun run = meshCadFile(path, absolute(0.001), false, "", backend, nullptr);
  REQUIRE(run.instanceCopies() == 39);
  const size_t triangles = run.mesh.mesh.triangleCount();
  const uint64_t saved = memoryBudget();
  setMemoryBudget(uint64_t(triangles) * 60);  // the part alone fits, its 40 placements do not
  try {
    meshCadFile(path, absolute(0.001), false, "", backend, nullptr);
    setMemoryBudget(saved);
    FAIL("40 copies were made past the memory budget");
  } catch (const MemoryLimitError& e) {
    setMemoryBudget(saved);
    INFO(e.what());
    CHECK(std::string(e.what()).find("39 placed copies of its parts") != std::string::npos);
  }
  // Listed, the copies make no triangles: the part alone, within the same budget.
  setMemoryBudget(uint64_t(triangles) * 60);
  CadMeshRun listed;
  CHECK_NOTHROW(listed = meshCadFile(path, absolute(0.001), false, "", backend, nullptr, 0,
                                     CopyPlacement::Listed));
  setMemoryBudget(saved);
  CHECK(listed.mesh.mesh.triangleCount() * 40 == triangles);
  CHECK(listed.mesh.faces.size() == run.mesh.faces.size());
  // Listed, the copies' face stats are still held to it (a board's 10⁵ parts): the copying
  // step alone, on the part's mesh, under a budget its 40 placements' stats exceed.
  const CadFile file = readCadFile(path);
  const InstancePlan plan = planInstances(file.shape);
  REQUIRE(plan.copies.size() == 39);
  const CadImport import = toTrimmedModel(CadFile{file.path, plan.meshShape, file.faceEntities},
                                          0.001, 0, plan.numbering);
  TrimmedMeshOptions options;
  options.tolerance = 0.001;
  TrimmedMesh partMesh = meshTrimmedModel(import.model, options, backend, nullptr);
  std::vector<uint32_t> numbers;
  for (const TrimmedFace& face : import.model.faces) numbers.push_back(face.faceIndex);
  REQUIRE(partMesh.faces.size() == 3);
  const uint64_t statsOfAll = 120 * (sizeof(TrimmedFaceStats) + sizeof(uint32_t));
  setMemoryBudget(statsOfAll - 1);
  try {
    addInstanceCopies(plan, partMesh, numbers, CopyPlacement::Listed);
    setMemoryBudget(saved);
    FAIL("the faces' stats of 39 copies were made past the memory budget");
  } catch (const MemoryLimitError& e) {
    setMemoryBudget(saved);
    INFO(e.what());
    CHECK(std::string(e.what()).find("the faces' stats of 39 placed copies") != std::string::npos);
  }
  setMemoryBudget(statsOfAll);
  CHECK_NOTHROW(addInstanceCopies(plan, partMesh, numbers, CopyPlacement::Listed));
  setMemoryBudget(saved);
  CHECK(partMesh.faces.size() == 120);
  CHECK(numbers.size() == 120);
}

TEST_CASE("cad instances: a face that fails is named at every instance", "[cad][instances]") {
  test::ScratchDir dir("cad_instances");
  const TopoDS_Shape bad = test::degreeEightFace();
  const std::string path =
      written(dir, "bad_twice.brep",
              compoundOf({bad, BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 5), 1.0, 1.0, 1.0).Shape(),
                          bad.Moved(translation(0, 0, 10))}));
  Backend backend = makeMirrorBackend();
  try {
    meshCadFile(path, ToleranceSpec{}, false, "--skip-bad-faces", backend, nullptr);
    FAIL("a model with faces that do not convert was meshed");
  } catch (const InputError& e) {
    INFO(e.what());
    CHECK(std::string(e.what()).find("2 of 8 faces could not be converted") != std::string::npos);
    CHECK(std::string(e.what()).find("face 0: ") != std::string::npos);
    CHECK(std::string(e.what()).find("face 7: ") != std::string::npos);
  }
  const CadMeshRun run = meshCadFile(path, ToleranceSpec{}, true, "", backend, nullptr);
  CHECK(run.instanceCopies() == 1);
  REQUIRE(run.failures.size() == 2);
  CHECK(run.failures[0].find(path + ": face 0: ") == 0);
  CHECK(run.failures[1].find(path + ": face 7: ") == 0);
  CHECK(run.mesh.faces.size() == 6);
  CHECK(run.mesh.mesh.triangleCount() == 12);
}

// Hidden: run by CTest as the setup of the CLI's assembly tests (tests/CMakeLists.txt): four
// placements of CAP_50SGV_8_10 written as one STEP assembly by Open CASCADE's writer.
TEST_CASE("cad instances: write the CLI's STEP assembly", "[.cad-assembly-file]") {
  const CadFile cap = readCadFile("/usr/share/freecad/Mod/Idf/Idflibs/CAP_50SGV_8_10.stp");
  gp_Trsf turn;
  turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 1.0);
  std::vector<TopoDS_Shape> placed;
  for (int k = 0; k < 4; ++k)
    placed.push_back(cap.shape.Moved(TopLoc_Location(translation(20.0 * k, 0, 0).Transformation() *
                                                     (k % 2 ? turn : gp_Trsf()))));
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  STEPControl_Writer writer;
  REQUIRE(writer.Transfer(compoundOf(placed), STEPControl_AsIs) == IFSelect_RetDone);
  const std::string path = std::string(TESSERA_BINARY_DIR) + "/tests/cad_assembly.step";
  REQUIRE(writer.Write(path.c_str()) == IFSelect_RetDone);
  CHECK(planInstances(readCadFile(path).shape).copies.size() == 3);
}
