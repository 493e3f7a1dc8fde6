// The public CAD API (include/tessera/cad.h) against the CLI's own CAD run (cad/mesh_cad_file.h)
// on a model of FreeCAD's IDF library: the same mesh, faces named per triangle and per vertex,
// within δ, typed errors.
#include <catch2/catch.hpp>

#ifdef TESSERA_HAVE_CAD
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>
#include <tessera/cad.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "api/tessellator_access.h"
#include "cad_test_shapes.h"
#include "cad/mesh_cad_file.h"
#include "common/worker_pool.h"
#include "gpu_test_context.h"
#include "mesh/tessellate.h"
#include "mesh_checks.h"
#include "trim/trim_classifier.h"
#include "scratch_dir.h"
#include "vk/context.h"

namespace {
const std::string kSot23 = "/usr/share/freecad/Mod/Idf/Idflibs/SOT23.stp";
}

TEST_CASE("public CAD API: a STEP model is the CLI's mesh, faces named, closed", "[cad][api]") {
  tessera::Tessellator tessellator({tessera::Device::Cpu});
  const tessera::CadMesh cad = tessera::tessellateCadFile(tessellator, kSot23);

  tessera::Backend backend = tessera::makeMirrorBackend();
  const tessera::CadMeshRun run =
      tessera::meshCadFile(kSot23, tessera::ToleranceSpec{}, false, "", backend, nullptr);
  REQUIRE(cad.tolerance == run.delta);                 // 0.1% of the diagonal by default
  REQUIRE(cad.tolerance == Approx(1e-3 * run.diagonal).epsilon(1e-12));
  REQUIRE(cad.mesh.indices == run.mesh.mesh.indices);  // the same mesh, bit for bit
  REQUIRE(cad.mesh.positions.size() == 3 * run.mesh.mesh.positions.size());
  for (size_t v = 0; v < run.mesh.mesh.positions.size(); ++v)
    for (int d = 0; d < 3; ++d)
      REQUIRE(cad.mesh.positions[3 * v + size_t(d)] == run.mesh.mesh.positions[v][d]);

  REQUIRE(cad.faces == run.faces);
  REQUIRE(cad.facesMeshed == cad.faces);  // SOT23 converts whole
  REQUIRE(cad.skippedFaces.empty());
  REQUIRE(cad.triangleFaces.size() == cad.mesh.triangleCount());
  const std::set<uint32_t> faces(cad.triangleFaces.begin(), cad.triangleFaces.end());
  REQUIRE(faces.size() == cad.faces);  // every face has triangles, indices 0..faces-1
  REQUIRE(*faces.rbegin() == cad.faces - 1);
  // A vertex's patchIds is a face one of its triangles lies on.
  std::vector<std::set<uint32_t>> facesOfVertex(cad.mesh.vertexCount());
  for (size_t t = 0; t < cad.mesh.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k)
      facesOfVertex[cad.mesh.indices[3 * t + size_t(k)]].insert(cad.triangleFaces[t]);
  for (size_t v = 0; v < cad.mesh.vertexCount(); ++v)
    REQUIRE(facesOfVertex[v].count(cad.mesh.patchIds[v]) == 1);

  INFO("SOT23: " << cad.mesh.triangleCount() << " triangles, deviation " << cad.maxDeviation
                 << " of δ " << cad.tolerance);
  REQUIRE(cad.maxDeviation > 0);
  REQUIRE(cad.maxDeviation <= cad.tolerance);
  REQUIRE(cad.maxParametricDeviation <= cad.tolerance);
  const tessera::test::EdgeCensus census = tessera::test::censusOf(run.mesh.mesh, 0.0);
  // SOT23's faces are not sewn into a closed shell (OCCT's own check; test_cad_mesh.cpp holds
  // closure where it is): no edge used thrice or twice the same way.
  REQUIRE(census.overusedEdges == 0);
  REQUIRE(census.inconsistentEdges == 0);

  // Model units, and tighter: more triangles.
  tessera::CadOptions fine;
  fine.tolerance = cad.tolerance / 4;
  const tessera::CadMesh finer = tessera::tessellateCadFile(tessellator, kSot23, fine);
  REQUIRE(finer.tolerance == fine.tolerance);
  REQUIRE(finer.mesh.triangleCount() > cad.mesh.triangleCount());
  REQUIRE(finer.maxDeviation <= fine.tolerance);

  // One thread: the same mesh (the import and the cuts join their faces in order).
  tessera::CadOptions serial;
  serial.threads = 1;
  const tessera::CadMesh one = tessera::tessellateCadFile(tessellator, kSot23, serial);
  REQUIRE(one.mesh.indices == cad.mesh.indices);
  REQUIRE(one.mesh.positions == cad.mesh.positions);
  REQUIRE(one.triangleFaces == cad.triangleFaces);
}

// TessellatorOptions::threads caps CadOptions::threads (the smaller non-zero holds): the import
// and the cuts of a tessellator with threads = 1 stay on the calling thread, same mesh.
TEST_CASE("public CAD API: a tessellator's threads = 1 keeps the CAD run on its thread",
          "[cad][api][threads]") {
  tessera::TessellatorOptions oneThread;
  oneThread.device = tessera::Device::Cpu;
  oneThread.threads = 1;
  tessera::Tessellator wide({tessera::Device::Cpu}), narrow(oneThread);
  tessera::CadOptions manyThreads;
  manyThreads.threads = 8;
  const tessera::CadMesh expected = tessera::tessellateCadFile(wide, kSot23, manyThreads);
  const size_t workerPartsBefore = tessera::worker_pool::partsRunByWorkers();
  const tessera::CadMesh capped = tessera::tessellateCadFile(narrow, kSot23, manyThreads);
  REQUIRE(tessera::worker_pool::partsRunByWorkers() == workerPartsBefore);
  REQUIRE(capped.mesh.indices == expected.mesh.indices);
  REQUIRE(capped.mesh.positions == expected.mesh.positions);
}

TEST_CASE("public CAD API: errors are typed and name the file", "[cad][api]") {
  tessera::Tessellator tessellator({tessera::Device::Cpu});
  tessera::CadOptions bad;
  bad.tolerance = -1;
  REQUIRE_THROWS_AS(tessera::tessellateCadFile(tessellator, kSot23, bad), tessera::ArgumentError);
  bad.tolerance = 0;
  bad.relativeTolerance = 2;
  REQUIRE_THROWS_AS(tessera::tessellateCadFile(tessellator, kSot23, bad), tessera::ArgumentError);
  bad.relativeTolerance = 1e-10;  // under the smallest a CAD model takes (10⁻⁹ of its diagonal)
  REQUIRE_THROWS_WITH(tessera::tessellateCadFile(tessellator, kSot23, bad),
                      Catch::Contains("below the smallest a CAD model takes"));
  bad.relativeTolerance = 0.001;
  bad.tolerance = 1e-14;
  REQUIRE_THROWS_AS(tessera::tessellateCadFile(tessellator, kSot23, bad), tessera::ArgumentError);
  try {
    tessera::tessellateCadFile(tessellator, "no_such_model.step");
    FAIL("a missing file was read");
  } catch (const tessera::InputError& e) {
    REQUIRE(e.file() == "no_such_model.step");
  }
  REQUIRE_THROWS_AS(tessera::tessellateCadFile(tessellator, TESSERA_SOURCE_DIR "/data/teapot.bpt"),
                    tessera::InputError);  // not a CAD extension
}

// A face that cannot convert (degree 8) beside a box: an InputError naming the file and the face
// by default; with skipBadFaces the box alone, the face named in skippedFaces.
TEST_CASE("public CAD API: a face that fails is an error, or skipped and named", "[cad][api]") {
  tessera::test::ScratchDir dir("cad_api");
  const std::string path = (dir.path / "degree8_and_box.brep").string();
  TopoDS_Compound both;
  BRep_Builder builder;
  builder.MakeCompound(both);
  builder.Add(both, tessera::test::degreeEightFace());
  builder.Add(both, BRepPrimAPI_MakeBox(1.0, 1.0, 1.0).Shape());
  REQUIRE(BRepTools::Write(both, path.c_str()));
  tessera::Tessellator tessellator({tessera::Device::Cpu});
  try {
    tessera::tessellateCadFile(tessellator, path);
    FAIL("a model with a face that does not convert was meshed");
  } catch (const tessera::InputError& e) {
    INFO(e.what());
    REQUIRE(e.file() == path);
    REQUIRE(std::string(e.what()).find("1 of 7 faces could not be converted") != std::string::npos);
    REQUIRE(std::string(e.what()).find("face 0: ") != std::string::npos);
    REQUIRE(std::string(e.what()).find("CadOptions::skipBadFaces") != std::string::npos);
  }
  tessera::CadOptions skip;
  skip.skipBadFaces = true;
  const tessera::CadMesh box = tessera::tessellateCadFile(tessellator, path, skip);
  REQUIRE(box.faces == 7);
  REQUIRE(box.facesMeshed == 6);
  REQUIRE(box.skippedFaces.size() == 1);
  REQUIRE(box.skippedFaces[0].find(path + ": face 0: ") == 0);
  REQUIRE(box.emptyFaces.empty());
  REQUIRE(box.mesh.triangleCount() == 12);  // planes: two triangles a face
  REQUIRE(std::set<uint32_t>(box.triangleFaces.begin(), box.triangleFaces.end()) ==
          std::set<uint32_t>{1, 2, 3, 4, 5, 6});
}

// SOD_323 holds two zero-area slivers (wires back and forth along one line, 2.8e-7 wide): they
// mesh as nothing, with no error and no flag, each named in emptyFaces.
TEST_CASE("public CAD API: zero-area faces are empty, named, and no error", "[cad][api]") {
  const std::string path = "/usr/share/freecad/Mod/Idf/Idflibs/SOD_323.stp";
  tessera::Tessellator tessellator({tessera::Device::Cpu});
  const tessera::CadMesh cad = tessera::tessellateCadFile(tessellator, path);
  REQUIRE(cad.faces == 75);
  REQUIRE(cad.skippedFaces.empty());
  REQUIRE(cad.emptyFaces.size() == 2);
  REQUIRE(cad.emptyFaces[0].find(path + ": face 15 (#1859 ADVANCED_FACE): zero-area face") == 0);
  REQUIRE(cad.emptyFaces[1].find(path + ": face 26 (#2900 ADVANCED_FACE): zero-area face") == 0);
  REQUIRE(cad.facesMeshed == 73);
  const std::set<uint32_t> faces(cad.triangleFaces.begin(), cad.triangleFaces.end());
  REQUIRE(faces.count(15) == 0);
  REQUIRE(faces.count(26) == 0);
  REQUIRE(cad.maxDeviation <= cad.tolerance);
}

TEST_CASE("public CAD API: Vulkan gives the CPU's mesh", "[cad][api][gpu]") {
  tessera::Tessellator gpu({tessera::Device::Vulkan});
  REQUIRE(gpu.usesVulkan());
  WARN("public CAD API on " << gpu.deviceName());
  tessera::Tessellator cpu({tessera::Device::Cpu});
  const tessera::CadMesh a = tessera::tessellateCadFile(gpu, kSot23);
  const tessera::CadMesh b = tessera::tessellateCadFile(cpu, kSot23);
  REQUIRE(a.triangleFaces.size() == a.mesh.triangleCount());
  REQUIRE(a.maxDeviation <= a.tolerance);
  // The same run on the tests' context, whose validation layer is on: no message.
  tessera::Backend vulkan = tessera::makeVulkanBackend(tessera::test::gpuContext());
  const auto trim = tessera::makeVulkanTrimClassifier(tessera::test::gpuContext());
  const tessera::CadMeshRun validated =
      tessera::meshCadFile(kSot23, tessera::ToleranceSpec{}, false, "", vulkan, trim.get());
  tessera::test::requireValidationClean();
  REQUIRE(validated.mesh.mesh.triangleCount() == a.mesh.triangleCount());
  if (gpu.deviceName().find("llvmpipe") != std::string::npos) {
    REQUIRE(a.mesh.indices == b.mesh.indices);  // the trees and trim pass bit for bit
    REQUIRE(a.mesh.positions == b.mesh.positions);
    REQUIRE(a.triangleFaces == b.triangleFaces);
  } else {
    // Off lavapipe the trees' fp32 roundings may move a gap triangulation's choices
    // (test_trimmed_batched.cpp): the device's mesh within δ (above), its count within 1%.
    WARN("on " << gpu.deviceName() << ": " << a.mesh.triangleCount() << " triangles, CPU "
               << b.mesh.triangleCount());
    REQUIRE(std::abs(double(a.mesh.triangleCount()) - double(b.mesh.triangleCount())) <=
            0.01 * double(b.mesh.triangleCount()));
  }
}

TEST_CASE("public CAD API: a Tessellator builds its trim pipeline once, not per call",
          "[cad][api][gpu]") {
  // An engine or a batch job calls tessellateCadFile again and again on one Tessellator: the
  // trim classifier's pipeline (milliseconds to build on lavapipe) is kept like the backend's.
  tessera::Tessellator gpu({tessera::Device::Vulkan});
  const auto pipelinesBuilt = [&] {
    size_t built = 0;
    tessera::TessellatorAccess::run(gpu, [&](tessera::Backend&, tessera::vk::Context* context) {
      REQUIRE(context != nullptr);
      built = context->timings().pipelines;
    });
    return built;
  };
  const tessera::CadMesh first = tessera::tessellateCadFile(gpu, kSot23);
  const size_t builtByFirst = pipelinesBuilt();
  REQUIRE(builtByFirst > 0);
  const tessera::CadMesh second = tessera::tessellateCadFile(gpu, kSot23);
  REQUIRE(pipelinesBuilt() == builtByFirst);
  REQUIRE(second.mesh.indices == first.mesh.indices);  // the kept classifier, the same mesh
  REQUIRE(second.mesh.positions == first.mesh.positions);
}

#endif
