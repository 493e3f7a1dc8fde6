// A CAD file meshed at one δ, as the CLI (`tessera tessellate model.step`) and the public API
// (include/tessera/cad.h) both run it: read (cad_file.h), faces and edges converted
// (to_trimmed.h), trimmed faces meshed watertight across faces (trim/mesher.h).
// It declares no Open CASCADE type, so the CLI includes it in every build; tessera_cad defines
// meshCadFile.
#pragma once
#include <string>
#include <vector>

#include "io/gltf_writer.h"
#include "quadtree/tolerance.h"
#include "trim/mesher.h"

namespace tessera {

struct CadFile;  // cad/cad_file.h (Open CASCADE's shape): declared only, as this header is
                 // OCCT-free

// An assembly's part placed more than once is meshed once (cad/instances.h); its other
// placements, the copies, are that mesh moved. InMesh: their triangles follow the rest in
// CadMeshRun::mesh. Listed: the mesh holds each part once; the copies are only in
// glbInstances, for a caller that draws them instanced (the .glb's nodes, CadMesh::placements),
// and in the faces' stats. Either way the copies' faces are in mesh.faces.
enum class CopyPlacement { InMesh, Listed };

struct CadMeshRun {
  TrimmedMesh mesh;  // triangleFace: TrimmedFace::faceIndex, the face's index in the model
  // mesh.mesh.patchIds are positions in the list of faces that converted: their faceIndex.
  std::vector<uint32_t> faceIndexOfPosition;
  double delta = 0;          // δ in model units
  double diagonal = 0;       // the model's bounding-box diagonal
  size_t faces = 0;          // in the model
  size_t edges = 0, sharedPoints = 0;
  std::vector<std::string> failures;  // faces that did not convert, one message each
  std::vector<std::string> emptyFaces;  // faces of zero area, meshed as nothing: one message each
  std::vector<std::string> readerWarnings;  // what the STEP or IGES transfer warned of
  std::vector<std::string> warnings;  // edges off their faces' surfaces beyond tolerance
  std::vector<std::string> faceWarnings;  // faces whose gap refinement ran out of rounds over δ
  double maxChordDeviation = 0;       // measured over every edge's discretisation
  // An assembly's parts placed more than once are converted and meshed once; their other
  // instances are that mesh moved (cad/instances.h). sharedPoints counts such a part's once.
  // As glTF instances (io/gltf_writer.h): the mesh's vertices and triangles before the copies,
  // the parts' faces and each copy's matrix. No placements: nothing copied.
  GlbInstances glbInstances;
  size_t instancedParts() const { return glbInstances.parts.size(); }
  size_t instanceCopies() const { return glbInstances.placements.size(); }
  // The copies' vertices and triangles that CopyPlacement::Listed left out of the mesh (0
  // InMesh), and the whole model's counts either way (what the CLI reports).
  uint64_t listedVertices = 0, listedTriangles = 0;
  uint64_t modelVertices() const { return mesh.mesh.vertexCount() + listedVertices; }
  uint64_t modelTriangles() const { return mesh.mesh.triangleCount() + listedTriangles; }
  double readMs = 0, importMs = 0, meshMs = 0;
};

// The smallest δ a CAD model takes, as a share of its diagonal. Below it the edges' measured
// chords come within about 10⁴ ulps of their points' rounding, and a run only ends at the memory
// or node budget after many seconds to minutes (CAP_50SGV_8_10.stp, diagonal 16.7, on 2 cores:
// 10⁻⁹ of it exit 4 after 6 s, 10⁻¹⁰ after 33 s, 10⁻¹¹ still running after 100 s; at 10⁻¹⁴
// in model units it once filled 2 GiB in 8 s and went on).
inline constexpr double kSmallestRelativeCadTolerance = 1e-9;

// Reads and meshes `path` at `tolerance` (model units, or a share of the model's diagonal; not
// pixels, nor under kSmallestRelativeCadTolerance of the diagonal: std::invalid_argument naming
// the file and the smallest δ it takes) on `backend`, its trees' trim pass on `trim` (null: the CPU
// mirror). A face that does not convert is an InputError naming the file and every failed
// face, unless skipBadFaces (then they are listed in CadMeshRun::failures and the others
// meshed); `skipHint` names how the caller asks for that ("--skip-bad-faces"). `threads`: the
// CPU threads of the import and the cuts (0: all cores); the mesh is the same whatever it is.
CadMeshRun meshCadFile(const std::string& path, const ToleranceSpec& tolerance, bool skipBadFaces,
                       const std::string& skipHint, Backend& backend, TrimClassifier* trim,
                       unsigned threads = 0, CopyPlacement copies = CopyPlacement::InMesh);

// meshCadFile's work after the read, on a file already read (cad_file.h), with the mesher's
// options (their tolerance is set from `tolerance`): what a caller that reads once and meshes
// many times calls (bench_assembly).
CadMeshRun meshCadModel(const CadFile& file, const ToleranceSpec& tolerance, bool skipBadFaces,
                        const std::string& skipHint, Backend& backend, TrimClassifier* trim,
                        TrimmedMeshOptions options = {},
                        CopyPlacement copies = CopyPlacement::InMesh);

}  // namespace tessera
