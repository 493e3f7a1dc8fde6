#include "mesh_arrays.h"

namespace tessera::python {

namespace {

py::object proofToPython(const std::optional<tessera::ToleranceProof>& proof) {
  if (!proof) return py::none();
  py::dict d;
  d["tolerance"] = proof->tolerance;
  d["largest_bound"] = proof->largestBound;
  d["proven"] = proof->proven;
  return d;
}

}  // namespace

PyMesh toPython(const tessera::Mesh& mesh) {
  const auto n = static_cast<py::ssize_t>(mesh.vertexCount());
  const auto m = static_cast<py::ssize_t>(mesh.triangleCount());
  return {toArray(mesh.positions, {n, 3}), toArray(mesh.normals, {n, 3}), toArray(mesh.uvs, {n, 2}),
          toArray(mesh.patchIds, {n}), toArray(mesh.indices, {m, 3}), proofToPython(mesh.proof)};
}

}  // namespace tessera::python
