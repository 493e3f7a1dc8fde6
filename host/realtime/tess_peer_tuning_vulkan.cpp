// The peer's screen error on sampled views, and the search of its factor scale
// (host/realtime/tess_peer_tuning.h).
#include "realtime/tess_peer_tuning.h"

#include <algorithm>
#include <cmath>

#include "geometry/bezier.h"

namespace tessera {
namespace {

// A corner is on its patch when it is within fp32 rounding of the double surface at its
// (u, v), relative to the patch's coordinates (the evaluation stage computes in fp32).
size_t cornersOffPatch(const std::vector<gpu::TessPeerTriangle>& triangles,
                       const std::vector<BezierPatch>& patches) {
  size_t off = 0;
  for (const gpu::TessPeerTriangle& t : triangles) {
    if (t.patchIndex >= patches.size()) {
      off += 3;
      continue;
    }
    const BezierPatch& patch = patches[t.patchIndex];
    double size = 1.0;
    for (const glm::dvec3& c : patch.cp)
      size = std::max(size, std::max(std::abs(c.x), std::max(std::abs(c.y), std::abs(c.z))));
    const glm::vec2 uv[3] = {{t.uv01.x, t.uv01.y}, {t.uv01.z, t.uv01.w}, t.uv2};
    for (int k = 0; k < 3; ++k)
      off += glm::length(patchPoint(patch, uv[k].x, uv[k].y) -
                         glm::dvec3(glm::vec3(t.corners[k]))) > 1e-4 * size;
  }
  return off;
}

}  // namespace

PeerScreenError measurePeerScreenError(TessShaderPeer& peer,
                                       const std::vector<BezierPatch>& patches,
                                       const std::vector<PeerView>& views, int subdivisions) {
  PeerScreenError report;
  for (const PeerView& view : views) {
    const std::vector<gpu::TessPeerTriangle> triangles = peer.captureFrame(view.viewProjection);
    report.cornersOffPatch += cornersOffPatch(triangles, patches);
    const ScreenErrorReport e = measureScreenError(triangles, patches, view.camera, subdivisions);
    report.maxAffinePixels = std::max(report.maxAffinePixels, e.maxAffinePixels);
    report.maxPerspectivePixels = std::max(report.maxPerspectivePixels, e.maxPerspectivePixels);
    report.triangles += e.triangles;
    report.samples += e.samples;
  }
  return report;
}

FactorScaleSearch searchFactorScale(TessShaderPeer& peer, const std::vector<BezierPatch>& patches,
                                    const std::vector<PeerView>& views, double tolerancePixels,
                                    float resolution, float maxScale) {
  FactorScaleSearch search;
  // A trial stops at the first view above the tolerance (measuring is most of the cost).
  auto within = [&](float scale) {
    peer.setFactorScale(scale);
    FactorScaleTrial trial{scale, {}, 0};
    for (const PeerView& view : views) {
      const PeerScreenError e = measurePeerScreenError(peer, patches, {view});
      trial.error.maxAffinePixels = std::max(trial.error.maxAffinePixels, e.maxAffinePixels);
      trial.error.maxPerspectivePixels =
          std::max(trial.error.maxPerspectivePixels, e.maxPerspectivePixels);
      trial.error.triangles += e.triangles;
      trial.error.samples += e.samples;
      trial.error.cornersOffPatch += e.cornersOffPatch;
      ++trial.viewsMeasured;
      if (e.cornersOffPatch > 0 || e.maxAffinePixels > tolerancePixels) break;
    }
    search.trials.push_back(trial);
    search.captureWrong = search.captureWrong || trial.error.cornersOffPatch > 0;
    return !search.captureWrong && trial.error.maxAffinePixels <= tolerancePixels;
  };
  float below = 0.0f, above = 1.0f;  // measured above the tolerance / within it
  while (!within(above)) {
    if (above >= maxScale || search.captureWrong) {
      search.scale = above;
      return search;
    }
    below = above;
    above = std::min(1.5f * above, maxScale);
  }
  search.met = true;
  while (below > 0.0f && above - below > resolution) {
    const float middle = 0.5f * (below + above);
    (within(middle) ? above : below) = middle;
    if (search.captureWrong) {
      search.met = false;
      return search;
    }
  }
  search.scale = above;
  peer.setFactorScale(above);
  return search;
}

}  // namespace tessera
