// Measuring the tessellation-shader peer's screen error and tuning it to a tolerance (bench
// case 5): its factor rule as derived overshoots the tolerance, so an equal-error comparison
// needs the smallest factor scale (TessPeerOptions::factorScale) at which its triangles, as
// drawn on given views, measure within it. Searched by measurement, never assumed.
#pragma once
#include <glm/glm.hpp>

#include <vector>

#include "geometry/patch.h"
#include "realtime/frame.h"
#include "realtime/tess_shader_peer.h"

namespace tessera {

// One view of the peer: the matrix it draws with (float, as a renderer builds it) and the
// camera the error is measured against.
struct PeerView {
  glm::mat4 viewProjection;
  Camera camera;
};

// The peer's screen error, and the captured corners that are not on their patch at their
// (u, v): a capture the device got wrong (lavapipe, past about a million triangles a frame,
// gave some triangles another patch's index), which no one should trust.
struct PeerScreenError : ScreenErrorReport {
  size_t cornersOffPatch = 0;
};

// The largest screen error over `views` of the triangles the peer draws there (captureFrame,
// then measureScreenError against the double patches); triangles, samples and corners off
// their patch summed. Needs capturesTriangles().
PeerScreenError measurePeerScreenError(TessShaderPeer& peer,
                                       const std::vector<BezierPatch>& patches,
                                       const std::vector<PeerView>& views, int subdivisions = 2);

struct FactorScaleTrial {
  float scale;
  PeerScreenError error;     // over the views measured
  size_t viewsMeasured = 0;  // all of them, or up to the first above the tolerance
};

struct FactorScaleSearch {
  float scale = 1.0f;  // the smallest scale found whose largest affine error is ≤ the tolerance
  bool met = false;    // false: not even maxScale met it, or a capture was wrong
  bool captureWrong = false;  // a trial's capture had corners off their patch: search stopped
  std::vector<FactorScaleTrial> trials;  // in the order measured
};

// Measures scale 1, then grows it by half until the views' largest affine error (what both
// Tessera's counts and the peer's rule target) is within `tolerancePixels` (at most maxScale;
// a trial stops at its first view above it), then bisects the last bracket until it is
// narrower than `resolution`: the result's error was
// measured within the tolerance, and a scale `resolution` below it (or less) was measured
// above. Assumes the error falls as the scale grows, which rounding factors up makes true only
// roughly. A trial whose capture has corners off their patch stops the search, not met.
// Leaves the peer at the scale found.
FactorScaleSearch searchFactorScale(TessShaderPeer& peer, const std::vector<BezierPatch>& patches,
                                    const std::vector<PeerView>& views, double tolerancePixels,
                                    float resolution = 0.05f, float maxScale = 8.0f);

}  // namespace tessera
