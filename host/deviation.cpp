#include "deviation.h"

#include <algorithm>
#include <stdexcept>

#include "bezier.h"
#include "bicubic.h"
#include "closest_point.h"
#include "tessellate.h"

namespace tessera {

const char* deviationMetricName(DeviationMetric metric) {
  return metric == DeviationMetric::Parametric ? "parametric" : "geometric";
}

DeviationReport measureDeviation(const Tessellation& tessellation,
                                 const std::vector<BezierPatch>& patches, int subdivisions,
                                 DeviationMetric metric) {
  const TriangleMesh& mesh = tessellation.mesh;
  if (tessellation.trianglePatch.size() * 3 != mesh.indices.size() ||
      tessellation.cornerUv.size() != mesh.indices.size())
    throw std::invalid_argument("measureDeviation: per-triangle patches and corner uvs missing");
  if (subdivisions < 1) throw std::invalid_argument("measureDeviation: subdivisions must be >= 1");
  DeviationReport report;
  report.perPatchMax.assign(patches.size(), 0.0);
  report.perPatchMean.assign(patches.size(), 0.0);
  std::vector<size_t> perPatchSamples(patches.size(), 0);
  double sum = 0;
  const int n = subdivisions;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    const BezierPatch& patch = patches.at(tessellation.trianglePatch[t / 3]);
    const glm::dvec2 uvA(tessellation.cornerUv[t]), uvB(tessellation.cornerUv[t + 1]),
        uvC(tessellation.cornerUv[t + 2]);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        double wa = double(i) / n, wb = double(j) / n, wc = 1.0 - wa - wb;
        glm::dvec2 uv = wa * uvA + wb * uvB + wc * uvC;
        glm::dvec3 p = wa * glm::dvec3(mesh.positions[a]) + wb * glm::dvec3(mesh.positions[b]) +
                       wc * glm::dvec3(mesh.positions[c]);
        glm::dvec3 truth = patch.degreeU == 3 && patch.degreeV == 3
                               ? bicubicDerivatives(patch, uv.x, uv.y).p
                               : patchPoint(patch, uv.x, uv.y);
        double d = metric == DeviationMetric::Parametric
                       ? glm::length(p - truth)
                       : closestPointOnPatch(patch, p, uv).distance;
        const uint32_t patchIndex = tessellation.trianglePatch[t / 3];
        report.perPatchMax[patchIndex] = std::max(report.perPatchMax[patchIndex], d);
        report.perPatchMean[patchIndex] += d;
        ++perPatchSamples[patchIndex];
        sum += d;
        ++report.samples;
        if (d > report.maxDeviation) {
          report.maxDeviation = d;
          report.worstTriangle = t / 3;
        }
      }
  }
  report.meanDeviation = report.samples ? sum / double(report.samples) : 0.0;
  for (size_t p = 0; p < patches.size(); ++p)
    if (perPatchSamples[p]) report.perPatchMean[p] /= double(perPatchSamples[p]);
  return report;
}

}  // namespace tessera
