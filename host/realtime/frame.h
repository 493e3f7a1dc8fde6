// Real-time view-dependent tessellation (case 5 of bench/): every frame re-tessellates a scene
// of bicubic patches from scratch for one camera, with buffers kept between frames.
//   1. host: control points to screen-space homogeneous coordinates (screenSpacePatch),
//      patches whose control points all lie outside one side of the view frustum are culled
//      (the convex hull, hence the patch, is outside);
//   2. GPU: division counts N_u, N_v in pixels (split method, host/division/counter.h); a patch
//      the eye plane cuts (status Unbounded) is counted on the host by viewDivisions;
//   3. GPU: rule A, a uniform grid per patch evaluated by the grid evaluator of case 1
//      (host/realtime/grid_evaluator.h). It takes one P×P size per dispatch, so patches are bucketed by
//      P − 1 = max(N_u, N_v) rounded up to a short ladder of sizes: more cells than the counts
//      ask for, never fewer, so Filip's bound (division_count.h) still holds.
// Vertices stay in each bucket's mapped buffer (on lavapipe host memory), where a renderer
// would bind them; a grid's triangles are its cells split along (i, j)–(i+1, j+1).
// Not done here: stitching between neighbours of different sizes (T-junctions remain).
#pragma once
#include <memory>
#include <vector>

#include "realtime/grid_evaluator.h"
#include "geometry/patch.h"
#include "division/view_dependent.h"
#include "mesh/tessellate.h"

namespace tessera {
namespace vk {
class Context;
}
class DivisionCounter;

struct RealtimeOptions {
  double tolerancePixels = 1.0;
  int maxPerDirection = 64;  // counts above are clamped (reported as capped)
  // q of the split method (DivisionOptions::ratioPieces): the pieces on which the zero- and
  // negative-weight factors are bounded; a patch in front of the eye has neither.
  int ratioPieces = 4;
};

// One visible patch of a frame: its P×P grid, vertex (i, j) at vertices[i·P + j],
// u = i/(P−1), v = j/(P−1) (GridEvaluator's order).
struct RealtimeGrid {
  uint32_t patch = 0;
  uint32_t pointsPerSide = 0;
  int nu = 0, nv = 0;  // the counts asked for (≤ P − 1)
  const gpu::GridVertex* vertices = nullptr;
};

struct RealtimeFrame {
  std::vector<RealtimeGrid> grids;
  size_t culled = 0;    // patches dropped by the frustum test or found invisible
  size_t fallback = 0;  // patches the eye plane cuts, counted on the host
  size_t capped = 0;    // patches whose counts hit maxPerDirection
  size_t triangles = 0;
  size_t countedTriangles = 0;  // Σ 2·N_u·N_v: what the counts ask for, before the ladder
  size_t vertices = 0;
  size_t dispatches = 0;  // grid-evaluation submits (one per non-empty bucket)
  // Seconds: host transform, cull and packing; GPU counts (upload, dispatch, readback);
  // host fallback counts and bucketing; GPU grid evaluation (upload, dispatch, fence).
  double prepareSeconds = 0, countSeconds = 0, bucketSeconds = 0, gridSeconds = 0;
};

class RealtimeTessellator {
 public:
  // The context must outlive the tessellator. Throws std::invalid_argument for a patch that
  // is not bicubic or polynomial, a tolerance ≤ 0 or maxPerDirection outside 1..256.
  RealtimeTessellator(vk::Context& context, std::vector<BezierPatch> patches,
                      const RealtimeOptions& options = {});
  ~RealtimeTessellator();

  // Tessellates the whole scene for `camera`. The frame (and the vertices it points to) is
  // valid until the next call.
  const RealtimeFrame& tessellate(const Camera& camera);

  const std::vector<BezierPatch>& patches() const { return patches_; }

 private:
  std::vector<BezierPatch> patches_;
  std::vector<RationalBezierPatch> homogeneous_;  // weights 1, for the screen transform
  std::vector<gpu::BicubicPatch> gpuPatches_;
  RealtimeOptions options_;
  std::unique_ptr<DivisionCounter> counter_;
  std::vector<uint32_t> ladder_;  // grid sizes P − 1 of the buckets
  std::vector<std::unique_ptr<GridEvaluator>> evaluators_;  // one per bucket, buffers kept
  std::vector<std::vector<gpu::BicubicPatch>> bucketPatches_;
  std::vector<std::vector<size_t>> bucketGrids_;  // indices into frame_.grids
  RealtimeFrame frame_;
};

// P − 1 for counts (nu, nv) on a ladder of sizes: the smallest rung ≥ max(nu, nv).
uint32_t gridRung(const std::vector<uint32_t>& ladder, int nu, int nv);

// How far a frame's triangles are from the true surface on screen, in pixels. A triangle
// point (barycentric mix of its corners, sampled at (i, j, k)/n) is compared with the
// surface at the same mix of the corners' (u, v), both projected by `camera`:
// - affine: the mix taken in screen space — what Filip's bound on the screen-space patch
//   controls (the counts' guarantee);
// - perspective: the mix taken in world space (perspective-correct interpolation, what a
//   renderer interpolating uv shows).
// Truth is the double kernel (patchPoint); triangle corners are the GPU's fp32 vertices.
// Triangles with a corner at or behind the near plane, or with no corner on screen, are
// skipped (the rasterizer clips them).
struct ScreenErrorReport {
  double maxAffinePixels = 0, maxPerspectivePixels = 0;
  size_t triangles = 0, samples = 0;
};
ScreenErrorReport measureScreenError(const RealtimeFrame& frame,
                                     const std::vector<BezierPatch>& patches,
                                     const Camera& camera, int subdivisions = 2);
// The same for a mesh of rule T in pixels (mesh/screen_tolerance.h): each triangle against its
// own patch at its corners' (u, v) (Tessellation::trianglePatch, cornerUv).
ScreenErrorReport measureScreenError(const Tessellation& tessellation,
                                     const std::vector<BezierPatch>& patches,
                                     const Camera& camera, int subdivisions = 2);

}  // namespace tessera
