// The CAD import on several threads (host/cad/to_trimmed.cpp, docs/cad.md "Threads"): edges
// and faces convert in parallel and are put together in their order, so the import on one
// thread and on several must be the same bit for bit, and so must the mesh made from it.
#ifdef TESSERA_HAVE_CAD
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <string>
#include <type_traits>
#include <vector>

#include "cad/cad_file.h"
#include "cad/to_trimmed.h"
#include "mesh/tessellate.h"
#include "trim/mesher.h"

using namespace tessera;

namespace {

const char* kIdfLibrary = "/usr/share/freecad/Mod/Idf/Idflibs";

// Everything the import hands on, as bytes: equal bytes are an equal import.
class Bytes {
 public:
  std::string text;

  template <typename T>
  void add(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    text.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  template <typename T>
  void add(const std::vector<T>& values) {
    add(values.size());
    for (const T& value : values) add(value);
  }
  void add(const std::string& s) {
    add(s.size());
    text += s;
  }
};

std::string importBytes(const CadImport& in) {
  Bytes b;
  b.add(in.model.sharedPoints);
  b.add(in.pointTolerances);
  for (const TrimmedFace& face : in.model.faces) {
    b.add(face.faceIndex), b.add(face.label), b.add(face.reversed);
    b.add(face.revolution.profile), b.add(face.revolution.origin), b.add(face.revolution.axis);
    b.add(face.revolution.circleCentre), b.add(face.revolution.circleRadius);
    for (const BezierPatchPiece& piece : face.pieces) {
      b.add(piece.u0), b.add(piece.u1), b.add(piece.v0), b.add(piece.v1);
      b.add(piece.patch.degreeU), b.add(piece.patch.degreeV);
      b.add(piece.patch.cp), b.add(piece.patch.weights);
    }
    for (const TrimLoop& loop : face.loops) b.add(loop.uv), b.add(loop.pointIds);
  }
  b.add(in.uvBounds);
  for (const EdgeSamples& e : in.edgeSamples) {
    b.add(e.params), b.add(e.curvePoints);
    for (size_t k = 0; k < e.params.size(); ++k) b.add(e.pointId(k));
    b.add(e.degenerated), b.add(e.maxChordDeviation), b.add(e.tolerance);
  }
  for (const CadFaceFailure& f : in.failures) b.add(f.faceIndex), b.add(f.message);
  for (const CadFaceFailure& f : in.emptyFaces) b.add(f.faceIndex), b.add(f.message);
  for (const CadEdgeWarning& w : in.warnings) b.add(w.faceIndex), b.add(w.edgeIndex), b.add(w.gap), b.add(w.message);
  b.add(in.maxChordDeviation), b.add(in.loopsReversed);
  return b.text;
}

std::string meshBytes(const TrimmedMesh& mesh) {
  Bytes b;
  b.add(mesh.mesh.positions), b.add(mesh.mesh.uvs), b.add(mesh.mesh.patchIds);
  b.add(mesh.mesh.indices), b.add(mesh.triangleFace);
  return b.text;
}

}  // namespace

// SOD_323: two faces are empty (zero-area slivers), so they keep their order among the
// converted faces; CAP_50SGV_8_10: B-spline faces and edge warnings; RLF_7030: faces wrapping a
// whole period; the assembly: one part at two places, faces that share their surfaces.
TEST_CASE("cad: the import and its mesh are the same bit for bit on any number of threads", "[cad]") {
  const char* models[] = {"SOD_323.stp", "CAP_50SGV_8_10.stp", "RLF_7030.stp",
                          "I22_2_5_16withEPL22_6_16.stp"};
  Backend backend = makeMirrorBackend();
  for (const char* name : models) {
    const std::string path = std::string(kIdfLibrary) + "/" + name;
    INFO(path);
    REQUIRE(std::filesystem::exists(path));  // freecad-common (scripts/deps.sh installs it)
    const CadFile file = readCadFile(path);
    const double delta = defaultCadTolerance(file.shape);
    const CadImport serial = toTrimmedModel(file, delta, 1);
    REQUIRE(serial.model.faces.size() > 10);
    const std::string expected = importBytes(serial);
    // 4 threads however many cores: more threads than cores interleave them the most.
    for (const unsigned threads : {4u, 0u}) {
      INFO("threads " << threads);
      const CadImport parallel = toTrimmedModel(file, delta, threads);
      CHECK(parallel.model.faces.size() == serial.model.faces.size());
      CHECK(parallel.failures.size() == serial.failures.size());
      CHECK(parallel.emptyFaces.size() == serial.emptyFaces.size());
      CHECK(parallel.warnings.size() == serial.warnings.size());
      CHECK(importBytes(parallel) == expected);
    }
    TrimmedMeshOptions options;
    options.tolerance = delta;
    options.threads = 1;
    const TrimmedMesh one = meshTrimmedModel(serial.model, options, backend);
    options.threads = 0;
    const TrimmedMesh all = meshTrimmedModel(toTrimmedModel(file, delta, 0).model, options, backend);
    REQUIRE(one.mesh.triangleCount() > 0);
    CHECK(meshBytes(all) == meshBytes(one));
    std::printf(
        "cad threads: %s: %zu faces, %zu failed, %zu empty, %zu warnings, %zu triangles, "
        "the same import and mesh on 1, 4 and all threads\n",
        name, serial.model.faces.size(), serial.failures.size(), serial.emptyFaces.size(),
        serial.warnings.size(), one.mesh.triangleCount());
  }
}

#endif  // TESSERA_HAVE_CAD
