// tessera._core: the public API with numpy arrays (docs/python.md), re-exported by the package
// tessera (python/package_init.py). It links no Open CASCADE: CAD is tessera._cad's.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <tessera/tessera.h>

#include "mesh_arrays.h"

namespace py = pybind11;
using tessera::python::PyMesh;
using tessera::python::toArray;
using tessera::python::toPython;

namespace {

tessera::Rule parseRule(const std::string& name) {
  if (name == "A" || name == "a") return tessera::Rule::A;
  if (name == "B" || name == "b") return tessera::Rule::B;
  if (name == "C" || name == "c") return tessera::Rule::C;
  if (name == "D" || name == "d") return tessera::Rule::D;
  if (name == "T" || name == "t") return tessera::Rule::T;
  throw tessera::ArgumentError("rule must be 'A', 'B', 'C', 'D' or 'T', got '" + name + "'");
}

// The name of ToleranceOptions{}.method, the C++ default.
const char* const kDefaultToleranceMethod =
    tessera::ToleranceOptions{}.method == tessera::ToleranceMethod::Adaptive ? "adaptive"
                                                                             : "uniform";

tessera::ToleranceMethod parseToleranceMethod(const std::string& name) {
  if (name == "adaptive") return tessera::ToleranceMethod::Adaptive;
  if (name == "uniform") return tessera::ToleranceMethod::UniformGrids;
  throw tessera::ArgumentError("method must be 'adaptive' or 'uniform', got '" + name + "'");
}

tessera::Device parseDevice(const std::string& name) {
  if (name == "auto") return tessera::Device::Auto;
  if (name == "vulkan") return tessera::Device::Vulkan;
  if (name == "cpu") return tessera::Device::Cpu;
  throw tessera::ArgumentError("device must be 'auto', 'vulkan' or 'cpu', got '" + name + "'");
}

// A path (str or os.PathLike) → its patches; an array (n, degreeU+1, degreeV+1, 3) of control
// points (with `weights` (n, degreeU+1, degreeV+1) or None) → n patches.
std::vector<tessera::Patch> toPatches(const py::object& surface, const py::object& weights) {
  if (py::isinstance<py::str>(surface) || py::hasattr(surface, "__fspath__")) {
    if (!weights.is_none())
      throw tessera::ArgumentError("weights go with control points, not a file");
    return tessera::loadPatches(py::str(py::module_::import("os").attr("fspath")(surface)));
  }
  using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;
  const Doubles points = Doubles::ensure(surface);
  if (!points || points.ndim() != 4 || points.shape(3) != 3 || points.shape(1) < 2 ||
      points.shape(2) < 2)
    throw tessera::ArgumentError(
        "control points must be an array of shape (patches, degreeU+1, degreeV+1, 3)");
  const int degreeU = int(points.shape(1)) - 1, degreeV = int(points.shape(2)) - 1;
  Doubles w;
  if (!weights.is_none()) {
    w = Doubles::ensure(weights);
    if (!w || w.ndim() != 3 || w.shape(0) != points.shape(0) || w.shape(1) != points.shape(1) ||
        w.shape(2) != points.shape(2))
      throw tessera::ArgumentError(
          "weights must be an array of shape (patches, degreeU+1, degreeV+1)");
  }
  return tessera::patchesFromArrays(degreeU, degreeV, size_t(points.shape(0)), points.data(),
                                    weights.is_none() ? nullptr : w.data());
}

tessera::RuleOptions ruleOptions(const std::string& rule, float linearity, float flatness,
                                 std::pair<int, int> grid, int samples, uint32_t maxDepth,
                                 double tolerance = 0) {
  tessera::RuleOptions o;
  o.rule = parseRule(rule);
  o.tolerance = tolerance;
  o.linearity = linearity;
  o.flatness = flatness;
  o.gridU = grid.first;
  o.gridV = grid.second;
  o.samples = samples;
  o.maxDepth = maxDepth;
  return o;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "Tessera: free-form surfaces to triangle meshes on Vulkan or the CPU (docs/python.md)";
  m.attr("__version__") = tessera::version();
  // Everything here is tessera.X to its users (reprs, error messages, help()): pybind11 names
  // classes and functions after their scope's __module__ where it has one.
  m.attr("__module__") = "tessera";

  // Base first: pybind11 tries the translators registered last first, so subclasses win.
  const py::exception<tessera::Error>& error =
      py::register_exception<tessera::Error>(m, "Error", PyExc_RuntimeError);
  py::register_exception<tessera::InputError>(m, "InputError", error.ptr());
  py::register_exception<tessera::ArgumentError>(m, "ArgumentError", error.ptr());
  py::register_exception<tessera::LimitError>(m, "LimitError", error.ptr());
  py::register_exception<tessera::DeviceError>(m, "DeviceError", error.ptr());
  for (const char* name : {"Error", "InputError", "ArgumentError", "LimitError", "DeviceError"})
    m.attr(name).attr("__module__") = "tessera";  // register_exception uses __name__

  py::class_<PyMesh>(m, "Mesh", "An indexed triangle mesh as numpy arrays")
      .def_readonly("positions", &PyMesh::positions, "float32 (N, 3)")
      .def_readonly("normals", &PyMesh::normals, "float32 (N, 3)")
      .def_readonly("uvs", &PyMesh::uvs, "float32 (N, 2): each vertex's (u, v) on its patch")
      .def_readonly("patch_ids", &PyMesh::patch_ids, "uint32 (N,)")
      .def_readonly("indices", &PyMesh::indices, "uint32 (M, 3), counter-clockwise")
      .def_readonly("proof", &PyMesh::proof,
                    "tolerance calls: {'tolerance', 'largest_bound', 'proven'} (docs/api.md, "
                    "'What was proven'); None for rules A-D")
      .def("__repr__", [](const PyMesh& mesh) {
        return "<tessera.Mesh " + std::to_string(mesh.indices.shape(0)) + " triangles, " +
               std::to_string(mesh.positions.shape(0)) + " vertices>";
      });

  py::class_<tessera::Tessellator> tessellator(
      m, "Tessellator", "Keeps the device open: make one, tessellate many times");
  tessellator
      .def(py::init([](const std::string& device, const std::string& deviceName, unsigned threads) {
             return tessera::Tessellator({parseDevice(device), deviceName, threads});
           }),
           py::arg("device") = "auto", py::arg("device_name") = "", py::arg("threads") = 0u,
           "threads: the most CPU threads each parallel step of a call uses (0: all cores; 1: "
           "the calling thread only), as TessellatorOptions::threads")
      .def_property_readonly("device_name", &tessera::Tessellator::deviceName)
      .def_property_readonly("uses_vulkan", &tessera::Tessellator::usesVulkan)
      .def(
          "tessellate",
          [](tessera::Tessellator& self, const py::object& surface, const py::object& weights,
             const std::string& rule, float linearity, float flatness, std::pair<int, int> grid,
             int samples, uint32_t maxDepth, double tolerance) {
            const auto patches = toPatches(surface, weights);
            const auto options =
                ruleOptions(rule, linearity, flatness, grid, samples, maxDepth, tolerance);
            tessera::Mesh mesh;
            {
              py::gil_scoped_release unlocked;  // other Python threads run meanwhile
              mesh = self.tessellate(patches, options);
            }
            return toPython(mesh);
          },
          py::arg("surface"), py::arg("weights") = py::none(), py::arg("rule") = "B",
          py::arg("linearity") = 0.1f, py::arg("flatness") = 0.1f,
          py::arg("grid") = std::make_pair(8, 8), py::arg("samples") = 5, py::arg("max_depth") = 0u,
          py::arg("tolerance") = 0.0,
          "Adaptive tessellation of a file path or control points by split rule A-D, or T "
          "with `tolerance` (model units)")
      .def(
          "tessellate_to_tolerance",
          [](tessera::Tessellator& self, const py::object& surface, double tolerance,
             const py::object& weights, const std::string& method, int maxPerDirection,
             uint32_t maxDepth) {
            const auto patches = toPatches(surface, weights);
            tessera::ToleranceOptions options;
            options.method = parseToleranceMethod(method);
            options.maxPerDirection = maxPerDirection;
            options.maxDepth = maxDepth;
            tessera::Mesh mesh;
            {
              py::gil_scoped_release unlocked;
              mesh = self.tessellateToTolerance(patches, tolerance, options);
            }
            return toPython(mesh);
          },
          py::arg("surface"), py::arg("tolerance"), py::arg("weights") = py::none(),
          py::arg("method") = kDefaultToleranceMethod, py::arg("max_per_direction") = 1024,
          py::arg("max_depth") = 30u,
          "Every triangle within `tolerance` (model units) of the surface: method 'adaptive' "
          "(rule T's quad-tree) or 'uniform' (a grid per patch from Filip's bound)");
  // Tessellator.tessellate_cad and tessera.CadMesh come from tessera._cad, which links Open
  // CASCADE and is imported at the first CAD call (python/package_init.py): whether it was built.
  m.attr("_has_cad") = bool(TESSERA_PYTHON_HAS_CAD);

  m.def(
      "relative_tolerance",
      [](const py::object& surface, double fraction, const py::object& weights) {
        return tessera::relativeTolerance(toPatches(surface, weights), fraction);
      },
      py::arg("surface"), py::arg("fraction"), py::arg("weights") = py::none(),
      "fraction × the diagonal of the control points' bounding box, in model units "
      "(0.001: the CLI's default tolerance, 0.1%)");

  m.def(
      "tessellate",
      [](const py::object& surface, const py::object& weights, const std::string& rule,
         float linearity, float flatness, const std::string& device) {
        const auto patches = toPatches(surface, weights);
        const auto options = ruleOptions(rule, linearity, flatness, {8, 8}, 5, 12);
        tessera::Tessellator tessellator({parseDevice(device), ""});
        return toPython(tessellator.tessellate(patches, options));
      },
      py::arg("surface"), py::arg("weights") = py::none(), py::arg("rule") = "B",
      py::arg("linearity") = 0.1f, py::arg("flatness") = 0.1f, py::arg("device") = "auto",
      "One call: a Tessellator for this call only (keep one for repeated work)");

  m.def(
      "load_patches",
      [](const std::string& path) {
        py::list result;
        for (const tessera::Patch& p : tessera::loadPatches(path)) {
          const py::ssize_t nu = p.degreeU + 1, nv = p.degreeV + 1;
          py::object weights = py::none();
          if (!p.weights.empty()) weights = toArray(p.weights, {nu, nv});
          result.append(py::make_tuple(toArray(p.points, {nu, nv, 3}), weights));
        }
        return result;
      },
      py::arg("path"),
      "The patches of a file: a list of (points (du+1, dv+1, 3), weights or None)");
}
