// CAD files through Open CASCADE (issue 17, docs/cad.md): STEP (.step, .stp), IGES (.iges,
// .igs) and OCCT's own .brep, read into one TopoDS_Shape. Assemblies come out as located
// instances (TransferRoots + OneShape), each at its place. This stage is the only code that
// includes OCCT headers (CMake target tessera_cad); tessera_core never sees them.
#pragma once
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <string>
#include <unordered_map>
#include <vector>

namespace tessera {

struct CadFile {
  std::string path;
  TopoDS_Shape shape;
  // Each transferred face's source entity ("#345 AdvancedFace"), by the face's TShape: the
  // instances of an assembly share it whatever their location. Empty for .brep files and
  // shapes built in code.
  std::unordered_map<const TopoDS_TShape*, std::string> faceEntities;
  // What the STEP or IGES transfer warned of (exchange_checks.h, transferWarnings): one line
  // each, naming the file and the entities. Empty for .brep files.
  std::vector<std::string> readerWarnings;
};

// Throws InputError (tessera/errors.h) naming the file: an unknown extension, a file that
// cannot be opened or parsed (with the reader's status), or one that yields no shape.
CadFile readCadFile(const std::string& path);

// "#345 AdvancedFace" for a face transferred from a STEP entity, "entity 12 Face" for IGES;
// empty when the reader keeps no record of the face (a .brep file, a shape built in code).
// A reference into `file` (or to an empty string): no copy per face.
const std::string& faceEntityLabel(const CadFile& file, const TopoDS_Face& face);

}  // namespace tessera
