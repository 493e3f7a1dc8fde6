// tessera::Mesh as numpy arrays: the Python type `tessera.Mesh`, shared by the two extension
// modules (tessera._core defines it, tessera._cad returns it inside a CadMesh). Outside an
// anonymous namespace, so that pybind11 finds the one registered type from either module.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstring>
#include <optional>
#include <vector>

#include <tessera/tessera.h>

namespace tessera::python {

namespace py = pybind11;

struct PyMesh {
  py::array_t<float> positions, normals, uvs;
  py::array_t<uint32_t> patch_ids, indices;
  py::object proof;  // None, or a dict of tessera::ToleranceProof's members
};

// A copy of `values` as a numpy array of `shape` (the vector is freed with the Mesh).
template <class T>
py::array_t<T> toArray(const std::vector<T>& values, std::vector<py::ssize_t> shape) {
  py::array_t<T> array(shape);
  if (!values.empty()) std::memcpy(array.mutable_data(), values.data(), values.size() * sizeof(T));
  return array;
}

PyMesh toPython(const tessera::Mesh& mesh);

}  // namespace tessera::python
