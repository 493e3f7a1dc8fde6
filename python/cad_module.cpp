// tessera._cad: Tessellator.tessellate_cad and tessera.CadMesh (tessera/cad.h). A module of its
// own because it links Open CASCADE (~30 libraries and TBB); python/package_init.py imports it at
// the first CAD call, so `import tessera` loads none of them. The Tessellator and Mesh types
// are tessera._core's (pybind11 shares registered types between modules), and so are the
// exception translations. Both modules carry their own copy of libtessera.a (a static
// archive, symbols hidden): _cad's code runs on a Tessellator that _core built, which is sound
// because the copies are of one build and the Vulkan calls after a context exists go through
// that context's own function tables (vk/loader.h), not volk's globals, which only _core's
// copy has loaded.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <tessera/cad.h>

#include "mesh_arrays.h"

namespace py = pybind11;
using tessera::python::PyMesh;
using tessera::python::toArray;
using tessera::python::toPython;

namespace {

// A placement's motion as numpy holds a matrix: m[row, column], so m @ (x, y, z, 1) moves a
// point (CadPlacement::matrix is column-major).
py::array_t<double> rowMajor(const std::array<double, 16>& columnMajor) {
  py::array_t<double> out({4, 4});
  auto m = out.mutable_unchecked<2>();
  for (py::ssize_t row = 0; row < 4; ++row)
    for (py::ssize_t column = 0; column < 4; ++column)
      m(row, column) = columnMajor[size_t(4 * column + row)];
  return out;
}

struct PyCadPlacement {
  uint32_t part = 0, first_face = 0;
  py::array_t<double> matrix;
};

struct PyCadMesh {
  PyMesh mesh;
  py::array_t<uint32_t> triangle_faces;
  size_t faces = 0, faces_meshed = 0;
  std::vector<tessera::CadPart> parts;
  std::vector<PyCadPlacement> placements;
  double tolerance = 0, max_deviation = 0, max_parametric_deviation = 0;
  std::vector<std::string> skipped_faces, empty_faces, warnings;
};

PyCadMesh tessellateCad(tessera::Tessellator& tessellator, const py::object& path, double tolerance,
                        double relativeTolerance, bool skipBadFaces, bool expandInstances) {
  const std::string file = py::str(py::module_::import("os").attr("fspath")(path));
  tessera::CadOptions options;
  options.tolerance = tolerance;
  options.relativeTolerance = relativeTolerance;
  options.skipBadFaces = skipBadFaces;
  options.expandInstances = expandInstances;
  tessera::CadMesh cad;
  {
    py::gil_scoped_release unlocked;
    cad = tessera::tessellateCadFile(tessellator, file, options);
  }
  PyCadMesh out;
  out.mesh = toPython(cad.mesh);
  out.triangle_faces =
      toArray(cad.triangleFaces, {static_cast<py::ssize_t>(cad.triangleFaces.size())});
  out.faces = cad.faces;
  out.faces_meshed = cad.facesMeshed;
  out.parts = cad.parts;
  for (const tessera::CadPlacement& placed : cad.placements)
    out.placements.push_back({placed.part, placed.firstFace, rowMajor(placed.matrix)});
  out.tolerance = cad.tolerance;
  out.max_deviation = cad.maxDeviation;
  out.max_parametric_deviation = cad.maxParametricDeviation;
  out.skipped_faces = cad.skippedFaces;
  out.empty_faces = cad.emptyFaces;
  out.warnings = cad.warnings;
  return out;
}

}  // namespace

PYBIND11_MODULE(_cad, m) {
  m.doc() = "Tessera's CAD input (Open CASCADE), imported by tessera at the first CAD call";
  py::module_::import("tessera._core");  // registers Tessellator, Mesh and the exceptions
  m.attr("__module__") = "tessera";      // tessera.CadMesh, as tessera._core's classes

  py::class_<tessera::CadPart>(m, "CadPart",
                               "An assembly's part placed more than once, in CadMesh.mesh at its "
                               "first place: its ranges (docs/api.md)")
      .def_readonly("first_vertex", &tessera::CadPart::firstVertex)
      .def_readonly("vertex_count", &tessera::CadPart::vertexCount)
      .def_readonly("first_triangle", &tessera::CadPart::firstTriangle)
      .def_readonly("triangle_count", &tessera::CadPart::triangleCount)
      .def_readonly("first_face", &tessera::CadPart::firstFace, "its faces' numbers from here")
      .def_readonly("face_count", &tessera::CadPart::faceCount);
  py::class_<PyCadPlacement>(m, "CadPlacement", "Another place of a part: its mesh moved")
      .def_readonly("part", &PyCadPlacement::part, "index into CadMesh.parts")
      .def_readonly("matrix", &PyCadPlacement::matrix,
                    "float64 (4, 4), m[row, column]: m @ (x, y, z, 1) is the point moved "
                    "(rigid)")
      .def_readonly("first_face", &PyCadPlacement::first_face,
                    "this copy's number of the part's first face");

  py::class_<PyCadMesh>(m, "CadMesh", "A CAD model's mesh and what was measured (docs/api.md)")
      .def_readonly("mesh", &PyCadMesh::mesh, "the Mesh; patch_ids: a face each vertex is on")
      .def_readonly("triangle_faces", &PyCadMesh::triangle_faces,
                    "uint32 (M,): each triangle's face")
      .def_readonly("faces", &PyCadMesh::faces)
      .def_readonly("faces_meshed", &PyCadMesh::faces_meshed)
      .def_readonly("parts", &PyCadMesh::parts, "an assembly's parts placed more than once")
      .def_readonly("placements", &PyCadMesh::placements,
                    "their other places (in mesh too unless expand_instances=False)")
      .def_readonly("tolerance", &PyCadMesh::tolerance, "δ used, model units")
      .def_readonly("max_deviation", &PyCadMesh::max_deviation, "measured distance to the faces")
      .def_readonly("max_parametric_deviation", &PyCadMesh::max_parametric_deviation)
      .def_readonly("skipped_faces", &PyCadMesh::skipped_faces)
      .def_readonly("empty_faces", &PyCadMesh::empty_faces, "faces of zero area: no triangles")
      .def_readonly("warnings", &PyCadMesh::warnings)
      .def("__repr__", [](const PyCadMesh& c) {
        std::string text = "<tessera.CadMesh " + std::to_string(c.mesh.indices.shape(0)) +
                           " triangles, " + std::to_string(c.faces_meshed) + " of " +
                           std::to_string(c.faces) + " faces";
        if (!c.placements.empty())
          text += ", " + std::to_string(c.parts.size()) +
                  (c.parts.size() == 1 ? " part" : " parts") + " placed " +
                  std::to_string(c.placements.size()) + " more times";
        return text + ">";
      });
  // Tessellator.tessellate_cad (python/package_init.py) calls this with its arguments' defaults.
  m.def("tessellate_cad", &tessellateCad, py::arg("tessellator"), py::arg("path"),
        py::arg("tolerance"), py::arg("relative_tolerance"), py::arg("skip_bad_faces"),
        py::arg("expand_instances"),
        "A STEP, IGES or .brep model meshed watertight at `tolerance` (model units), or when 0 "
        "at `relative_tolerance` of its diagonal");
}
