#include "deviation.h"

#include <stdexcept>

#include "bezier.h"
#include "bicubic.h"

namespace tessera {

DeviationReport measureDeviation(const TriangleMesh& mesh, const std::vector<BezierPatch>& patches,
                                 int subdivisions) {
  if (mesh.uvs.size() != mesh.positions.size() || mesh.patchIds.size() != mesh.positions.size())
    throw std::invalid_argument("measureDeviation: the mesh needs uvs and patch ids");
  if (subdivisions < 1) throw std::invalid_argument("measureDeviation: subdivisions must be >= 1");
  DeviationReport report;
  double sum = 0;
  const int n = subdivisions;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    const BezierPatch& patch = patches.at(mesh.patchIds[a]);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        double wa = double(i) / n, wb = double(j) / n, wc = 1.0 - wa - wb;
        glm::dvec2 uv = wa * glm::dvec2(mesh.uvs[a]) + wb * glm::dvec2(mesh.uvs[b]) +
                        wc * glm::dvec2(mesh.uvs[c]);
        glm::dvec3 p = wa * glm::dvec3(mesh.positions[a]) + wb * glm::dvec3(mesh.positions[b]) +
                       wc * glm::dvec3(mesh.positions[c]);
        glm::dvec3 truth = patch.degreeU == 3 && patch.degreeV == 3
                               ? bicubicDerivatives(patch, uv.x, uv.y).p
                               : patchPoint(patch, uv.x, uv.y);
        double d = glm::length(p - truth);
        sum += d;
        ++report.samples;
        if (d > report.maxDeviation) {
          report.maxDeviation = d;
          report.worstTriangle = t / 3;
        }
      }
  }
  report.meanDeviation = report.samples ? sum / double(report.samples) : 0.0;
  return report;
}

}  // namespace tessera
