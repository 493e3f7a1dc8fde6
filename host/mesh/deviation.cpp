#include "mesh/deviation.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "common/parallel_for.h"
#include "geometry/bezier.h"
#include "geometry/bicubic.h"
#include "geometry/closest_point.h"
#include "mesh/tessellate.h"

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
  for (uint32_t patch : tessellation.trianglePatch)
    if (patch >= patches.size())
      throw std::invalid_argument("measureDeviation: patch " + std::to_string(patch) + " for " +
                                  std::to_string(patches.size()) + " patches");
  const size_t triangles = mesh.triangleCount();
  const int n = subdivisions;
  // Per triangle: largest and summed distance. Triangles are independent, so the work is
  // split over all cores and merged afterwards in triangle order (the result does not depend
  // on the thread count).
  std::vector<double> triangleMax(triangles, 0.0), triangleSum(triangles, 0.0);
  const bool inDouble = mesh.positionsDouble.size() == mesh.positions.size();
  const auto position = [&](uint32_t v) {
    return inDouble ? mesh.positionsDouble[v] : glm::dvec3(mesh.positions[v]);
  };
  auto measureRange = [&](size_t first, size_t last) {
    for (size_t t = first; t < last; ++t) {
      const BezierPatch& patch = patches[tessellation.trianglePatch[t]];
      const uint32_t* corner = &mesh.indices[3 * t];
      const glm::vec2* uv = &tessellation.cornerUv[3 * t];
      for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
          const double wa = double(i) / n, wb = double(j) / n, wc = 1.0 - wa - wb;
          const glm::dvec2 at = wa * glm::dvec2(uv[0]) + wb * glm::dvec2(uv[1]) + wc * glm::dvec2(uv[2]);
          const glm::dvec3 p =
              wa * position(corner[0]) + wb * position(corner[1]) + wc * position(corner[2]);
          double d;
          if (metric == DeviationMetric::Parametric) {
            const glm::dvec3 truth = patch.degreeU == 3 && patch.degreeV == 3
                                         ? bicubicDerivatives(patch, at.x, at.y).p
                                         : patchPoint(patch, at.x, at.y);
            d = glm::length(p - truth);
          } else {
            d = closestPointOnPatch(patch, p, at).distance;
          }
          triangleMax[t] = std::max(triangleMax[t], d);
          triangleSum[t] += d;
        }
    }
  };
  // Small meshes are not worth a thread start (the per-patch report measures each patch apart).
  parallelFor(triangles, triangles < 2048 ? 1u : 0u, measureRange);

  DeviationReport report;
  report.perPatchMax.assign(patches.size(), 0.0);
  report.perPatchMean.assign(patches.size(), 0.0);
  report.perPatchSamples.assign(patches.size(), 0);
  report.perPatchWorstTriangle.assign(patches.size(), 0);
  std::vector<size_t>& perPatchSamples = report.perPatchSamples;
  const size_t samplesPerTriangle = size_t(n + 1) * size_t(n + 2) / 2;
  double sum = 0;
  for (size_t t = 0; t < triangles; ++t) {
    const uint32_t patch = tessellation.trianglePatch[t];
    if (perPatchSamples[patch] == 0 || triangleMax[t] > report.perPatchMax[patch]) {
      report.perPatchMax[patch] = triangleMax[t];
      report.perPatchWorstTriangle[patch] = t;
    }
    report.perPatchMean[patch] += triangleSum[t];
    perPatchSamples[patch] += samplesPerTriangle;
    sum += triangleSum[t];
    if (triangleMax[t] > report.maxDeviation) {
      report.maxDeviation = triangleMax[t];
      report.worstTriangle = t;
    }
  }
  report.samples = triangles * samplesPerTriangle;
  report.meanDeviation = report.samples ? sum / double(report.samples) : 0.0;
  for (size_t p = 0; p < patches.size(); ++p)
    if (perPatchSamples[p]) report.perPatchMean[p] /= double(perPatchSamples[p]);
  return report;
}

}  // namespace tessera
