#include "surface_distance.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "bezier.h"
#include "bicubic.h"
#include "tessellate.h"

namespace tessera {
namespace {

SurfaceDerivatives derivatives(const BezierPatch& patch, double u, double v) {
  return patch.degreeU == 3 && patch.degreeV == 3 ? bicubicDerivatives(patch, u, v)
                                                   : patchDerivatives(patch, u, v);
}

}  // namespace

double distanceToPatch(const BezierPatch& patch, const glm::dvec3& point, glm::dvec2 uv) {
  double best = std::numeric_limits<double>::max();
  for (int iteration = 0; iteration < 12; ++iteration) {
    SurfaceDerivatives d = derivatives(patch, uv.x, uv.y);
    glm::dvec3 r = d.p - point;
    best = std::min(best, glm::length(r));
    // Newton on f = ½|r|²: gradient (Su·r, Sv·r), Hessian with the curvature terms.
    double gu = glm::dot(d.pu, r), gv = glm::dot(d.pv, r);
    double huu = glm::dot(d.pu, d.pu) + glm::dot(d.puu, r);
    double huv = glm::dot(d.pu, d.pv) + glm::dot(d.puv, r);
    double hvv = glm::dot(d.pv, d.pv) + glm::dot(d.pvv, r);
    double det = huu * hvv - huv * huv;
    glm::dvec2 step;
    if (det > 1e-300 && huu > 0) {
      step = glm::dvec2(hvv * gu - huv * gv, huu * gv - huv * gu) / det;
    } else {
      // Singular (a collapsed edge) or not convex here: a gradient step scaled by the metric.
      double g = glm::dot(d.pu, d.pu) + glm::dot(d.pv, d.pv);
      if (!(g > 0)) break;
      step = glm::dvec2(gu, gv) / g;
    }
    glm::dvec2 next = glm::clamp(uv - step, glm::dvec2(0.0), glm::dvec2(1.0));
    if (glm::length(next - uv) < 1e-13) break;
    uv = next;
  }
  return std::min(best, glm::length(derivatives(patch, uv.x, uv.y).p - point));
}

DeviationReport measureSurfaceDistance(const Tessellation& tessellation,
                                       const std::vector<BezierPatch>& patches,
                                       int subdivisions) {
  const TriangleMesh& mesh = tessellation.mesh;
  if (tessellation.trianglePatch.size() * 3 != mesh.indices.size() ||
      tessellation.cornerUv.size() != mesh.indices.size())
    throw std::invalid_argument("measureSurfaceDistance: per-triangle patches and uvs missing");
  if (subdivisions < 1)
    throw std::invalid_argument("measureSurfaceDistance: subdivisions must be >= 1");
  const size_t triangles = mesh.triangleCount();
  const int n = subdivisions;
  // Per triangle: largest and summed distance, and its sample count; merged after the threads.
  std::vector<double> triMax(triangles), triSum(triangles);
  auto work = [&](size_t first, size_t last) {
    for (size_t t = first; t < last; ++t) {
      const BezierPatch& patch = patches.at(tessellation.trianglePatch[t]);
      const uint32_t* idx = &mesh.indices[3 * t];
      const glm::vec2* uv = &tessellation.cornerUv[3 * t];
      for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
          double wa = double(i) / n, wb = double(j) / n, wc = 1.0 - wa - wb;
          glm::dvec2 start = wa * glm::dvec2(uv[0]) + wb * glm::dvec2(uv[1]) + wc * glm::dvec2(uv[2]);
          glm::dvec3 p = wa * glm::dvec3(mesh.positions[idx[0]]) +
                         wb * glm::dvec3(mesh.positions[idx[1]]) +
                         wc * glm::dvec3(mesh.positions[idx[2]]);
          double d = distanceToPatch(patch, p, start);
          triMax[t] = std::max(triMax[t], d);
          triSum[t] += d;
        }
    }
  };
  unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (unsigned k = 0; k < threads; ++k)
    pool.emplace_back(work, triangles * k / threads, triangles * (k + 1) / threads);
  for (auto& thread : pool) thread.join();

  DeviationReport report;
  report.perPatchMax.assign(patches.size(), 0.0);
  report.perPatchMean.assign(patches.size(), 0.0);
  std::vector<size_t> perPatchSamples(patches.size(), 0);
  const size_t samplesPerTriangle = size_t(n + 1) * size_t(n + 2) / 2;
  double sum = 0;
  for (size_t t = 0; t < triangles; ++t) {
    uint32_t patch = tessellation.trianglePatch[t];
    report.perPatchMax[patch] = std::max(report.perPatchMax[patch], triMax[t]);
    report.perPatchMean[patch] += triSum[t];
    perPatchSamples[patch] += samplesPerTriangle;
    sum += triSum[t];
    if (triMax[t] > report.maxDeviation) {
      report.maxDeviation = triMax[t];
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
