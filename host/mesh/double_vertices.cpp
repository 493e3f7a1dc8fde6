#include "mesh/double_vertices.h"

#include <stdexcept>
#include <string>

#include "geometry/bezier.h"
#include "geometry/general_patch.h"
#include "geometry/surface_normal.h"

namespace tessera {

void evaluateVerticesInDouble(TriangleMesh& mesh, const std::vector<BezierPatch>& patches) {
  const size_t count = mesh.vertexCount();
  if (mesh.uvs.size() != count || mesh.patchIds.size() != count)
    throw std::invalid_argument("evaluateVerticesInDouble: the mesh has no uv or patch id per vertex");
  std::vector<double> scale(patches.size());
  for (size_t p = 0; p < patches.size(); ++p) scale[p] = surfaceScale(patches[p]);
  mesh.positionsDouble.resize(count);
  if (!mesh.normals.empty()) mesh.normalsDouble.resize(count);
  for (size_t v = 0; v < count; ++v) {
    const uint32_t p = mesh.patchIds[v];
    if (p >= patches.size())
      throw std::invalid_argument("evaluateVerticesInDouble: vertex " + std::to_string(v) +
                                  " names patch " + std::to_string(p) + " of " +
                                  std::to_string(patches.size()));
    const double u = mesh.uvs[v].x, w = mesh.uvs[v].y;
    const SurfaceDerivatives d = patchDerivatives(patches[p], u, w);
    mesh.positionsDouble[v] = d.p;
    if (!mesh.normals.empty()) mesh.normalsDouble[v] = unitNormal(d, u, w, scale[p]);
  }
}

}  // namespace tessera
