// An assembly's repeated parts meshed once (docs/cad.md, "Assemblies"). A STEP or IGES
// assembly places one part at many places (a board's resistors): its shape holds the part's
// B-rep once, located many times. Open CASCADE's mesher meshes such a part once; Tessera meshed
// every instance from scratch (50 placed copies of CAP_50SGV_8_10: 3.2 s against BRepMesh's
// 0.09 s). Now the shape converted and meshed holds each part once, and its other instances
// are that mesh moved: the same triangles, within δ alike (the motion is rigid).
#pragma once
#include <TopoDS_Shape.hxx>
#include <gp_Trsf.hxx>
#include <vector>

#include "cad/cad_file.h"
#include "cad/mesh_cad_file.h"
#include "trim/mesher.h"
#include "cad/to_trimmed.h"
#include "io/gltf_writer.h"

namespace tessera {

// A part placed more than once. Its faces and edges at any place are numbered consecutively
// in the whole model (TopExp::MapShapes order): face k of the part (its own MapShapes order)
// is faceBase + k at its first place, a copy's faceBase + k at the copy's.
struct InstancedPart {
  TopoDS_Shape firstLeaf;  // the part at its first place, as the model holds it
  uint32_t faceBase = 0, edgeBase = 0;
  uint32_t faceCount = 0, edgeCount = 0;
};

// Another instance of a part: the first instance's mesh moved by `motion`.
struct InstanceCopy {
  size_t part = 0;  // index into InstancePlan::parts
  gp_Trsf motion;   // rigid: the first instance's place → this one's
  uint32_t faceBase = 0, edgeBase = 0;
};

struct InstancePlan {
  // The shape to convert and mesh: the file's shape without the instances after each part's
  // first. Null where no part is placed twice (then the file's shape is meshed as it is).
  TopoDS_Shape meshShape;
  CadNumbering numbering;  // meshShape's faces and edges by their numbers in the whole model
  size_t modelFaces = 0, modelEdges = 0;  // the whole model's counts
  std::vector<InstancedPart> parts;
  std::vector<InstanceCopy> copies;
};

// The parts placed more than once in `shape` (a compound's non-compound members, by their
// TShape). An instance is a copy only where it is its part's first moved rigidly (no scale, no
// mirror) with the same orientation, and the part shares no edge or vertex with another part
// (a copy could not weld to it). Any other instance is meshed in place, as before.
InstancePlan planInstances(const TopoDS_Shape& shape);

// planInstances of the file's shape, an Open CASCADE exception as an InputError naming the file
// (what meshCadFile and `tessera info` call).
InstancePlan planCadInstances(const CadFile& file);

// The model's bounding-box diagonal (cadModelDiagonal where nothing is copied): for an
// assembly, each part's box measured once and placed at every copy (BRepBndLib::Add over every
// placed face took 35 of the 56 ms of 50 copies of CAP_50SGV_8_10). A placed box bounds the
// copy, more loosely where the copy is turned: those 50 copies, turned by 0.3 rad each, give
// 214.3 where Open CASCADE's box of every face gives 210.3 (+1.9%; 0 for copies only moved),
// so a relative δ is that much larger. `tessera info` takes the same diagonal.
double plannedModelDiagonal(const InstancePlan& plan, const CadFile& file);

// The failures (or empty faces) of the parts' faces once more for each copy, named by the
// copy's numbers and the face's entity.
std::vector<CadFaceFailure> copiedFaceFailures(const InstancePlan& plan, const CadFile& file,
                                               const CadImport& import,
                                               const std::vector<CadFaceFailure>& failures);

// The edge warnings of the parts' faces once more for each copy.
std::vector<CadEdgeWarning> copiedEdgeWarnings(const InstancePlan& plan, const CadFile& file,
                                               const CadImport& import);

// Appends every copy to `mesh`, the mesh of plan.meshShape (triangleFace and patchIds:
// positions in the converted faces, faceNumberOfPosition their numbers): its faces' stats
// under the copy's numbers, at new positions appended to faceNumberOfPosition, and InMesh the
// part's vertices moved (normals turned) and its triangles. Copies do not weld to anything: a
// part shares no edge with the rest (planInstances).
// Returns the copies' vertices and triangles, whether put in the mesh or not, and each part's
// vertex and triangle ranges in the mesh before the copies.
struct CopiesSize {
  uint64_t vertices = 0, triangles = 0;
  std::vector<GlbInstances::Part> parts;  // plan.parts' faces and ranges
};
CopiesSize addInstanceCopies(const InstancePlan& plan, TrimmedMesh& mesh,
                             std::vector<uint32_t>& faceNumberOfPosition,
                             CopyPlacement placement = CopyPlacement::InMesh);

// The plan as glTF instances of a mesh whose first `vertices` and `triangles` are those before
// addInstanceCopies: each part (`parts`, as addInstanceCopies gave them), each copy's motion as
// a matrix and its face offset.
GlbInstances glbInstancesOf(const InstancePlan& plan, uint64_t vertices, uint64_t triangles,
                            std::vector<GlbInstances::Part> parts);

}  // namespace tessera
