// CAD models (docs/cad.md): STEP (.step, .stp), IGES (.iges, .igs) and Open CASCADE's .brep,
// read through Open CASCADE; every face (NURBS or analytic, trimmed by its loops) meshed at one
// tolerance, watertight across the faces' shared edges. Link tessera::cad
// (find_package(tessera COMPONENTS cad), or pkg-config tessera-cad): it brings Open CASCADE's
// libraries; this header names none of its types.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "tessera/tessera.h"

namespace tessera {

struct CadOptions {
  double tolerance = 0;              // δ in model units (> 0); 0: relativeTolerance below
  double relativeTolerance = 0.001;  // δ as this share of the model's bounding-box diagonal
                                     // when tolerance is 0 (0.1%, the CLI's default); (0, 1]
  // Either way δ must be at least 10⁻⁹ of the model's diagonal (ArgumentError naming the
  // smallest δ the model takes): below it the edges' chords are measured within their own
  // rounding, and the run could only end at the memory or node budget after minutes.
  // Mesh the faces that convert when some do not (each named in CadMesh::skippedFaces); off,
  // such a model is an InputError naming the file and every failed face.
  bool skipBadFaces = false;
  // CPU threads for converting the faces and cutting them along their trims; 0: all cores.
  // The tessellator's TessellatorOptions::threads caps it too (the smaller non-zero holds).
  // The mesh is the same, bit for bit, whatever the count.
  unsigned threads = 0;
  // An assembly's part placed more than once is meshed once and moved to its other places
  // (docs/cad.md, "Assemblies"). True: CadMesh::mesh holds every placement's triangles, the
  // copies after the rest. False: the mesh holds each part once, at its first place, and
  // CadMesh::placements says where else to draw it, for instanced drawing: the mesh and its
  // memory stay one part's size however often the part is placed.
  bool expandInstances = true;
};

// A part of an assembly placed more than once, as CadMesh::mesh holds it at its first place:
// ranges of its own (a part shares no vertex with the rest of the model).
struct CadPart {
  uint32_t firstVertex = 0, vertexCount = 0;      // in mesh.positions
  uint32_t firstTriangle = 0, triangleCount = 0;  // in mesh.indices / 3 and triangleFaces
  uint32_t firstFace = 0, faceCount = 0;          // its faces' numbers at its first place
};

// Another place of a part: the part's first place moved by `matrix`.
struct CadPlacement {
  uint32_t part = 0;  // index into CadMesh::parts
  // Column-major 4 × 4 (element [4 * column + row], as glTF and GLM), a rigid motion: no
  // scale, no mirror, so the moved triangles keep their winding and stay within δ.
  std::array<double, 16> matrix{};
  // The copy's faces are numbered firstFace + k where the part's are part.firstFace + k.
  uint32_t firstFace = 0;
};

struct CadMesh {
  // Per vertex: position, normal, uv (on the first face that uses it) and patchIds = that
  // face's index; vertices on an edge shared by two faces are one vertex (watertight).
  Mesh mesh;
  std::vector<uint32_t> triangleFaces;  // per triangle: its face's index in the model (faces
                                        // in Open CASCADE's TopExp order, from 0)
  size_t faces = 0;                     // faces in the model
  size_t facesMeshed = 0;               // those that converted and were meshed (not the
                                        // skipped faces nor the empty ones)
  double tolerance = 0;                 // δ used, model units
  // Measured over every triangle: the largest distance to its face's surface and the largest
  // parametric deviation (against the surface at the same mix of uv). Within δ plus the
  // file's own edge gaps (warnings), docs/trimmed_faces.md.
  double maxDeviation = 0, maxParametricDeviation = 0;
  std::vector<std::string> skippedFaces;  // with skipBadFaces: "<file>: face 3 (#345 ...): why"
  // Faces of zero area (a sliver whose wires run back and forth along one curve, as some
  // exporters write): nothing to mesh, so no triangles and no error; named here, one message
  // each ("<file>: face 15 (#1859 ADVANCED_FACE): zero-area face: its uv bounds are ...").
  std::vector<std::string> emptyFaces;
  // What Open CASCADE's STEP or IGES transfer warned of (its shape healing dropping a null-area
  // wire, say), edges off their faces beyond the file's tolerance, faces whose refinement ended
  // over δ: one message each, naming the file.
  std::vector<std::string> warnings;
  // An assembly's parts placed more than once, and their other placements (the moved copies;
  // none for a model without repeated parts). With CadOptions::expandInstances the copies are
  // in `mesh` too; without, only here. The counts and the stats above are the whole model's
  // either way (faces, facesMeshed, the deviations, the messages).
  std::vector<CadPart> parts;
  std::vector<CadPlacement> placements;
};

// Reads and meshes `path` on the tessellator's device (the trees and their trim pass; the
// cuts along the trim curves run on the CPU's cores). Throws InputError naming the file (and
// the faces) for an unreadable file, an unknown extension or faces that fail to convert
// (unless skipBadFaces), ArgumentError for a bad tolerance, DeviceError as
// Tessellator::tessellate. On Vulkan the tessellator keeps the trim pass's pipeline and buffers
// from its first call for the next ones (the buffers at the largest model's size).
CadMesh tessellateCadFile(Tessellator& tessellator, const std::string& path,
                          const CadOptions& options = {});

}  // namespace tessera
