// Real-time view-dependent tessellation (case 5 of bench/): every frame re-tessellates a scene
// of bicubic patches from scratch for one camera, with buffers kept between frames.
//   1. host: control points to screen-space homogeneous coordinates (screenSpacePoints),
//      patches whose control points all lie outside one side of the view frustum are culled
//      (the convex hull, hence the patch, is outside);
//   2. host: division counts in pixels for every visible patch (N_u, N_v) and every edge of a
//      visible patch (its segment count, from the edge's own control points alone:
//      host/realtime/patch_edges.h), from the screen-space control points in one pass each
//      (host/division/projected.h: an estimate by default, or a proven bound); a patch or
//      edge whose net reaches the near plane is counted by viewDivisions (split, else
//      subdivided, clipped to the view). Steps 1-2 run on the host's threads; nothing waits
//      on the GPU before the pattern;
//   3. GPU: the stitched pattern (shaders/stitch_pattern.comp.glsl, docs/realtime.md): per
//      patch an inner grid from (N_u, N_v) and a transition strip along each side to that
//      side's edge count. Both patches of a shared edge use its one count and evaluate its
//      vertices from its canonical control points, so the mesh has no T-junctions and no
//      cracks: shared vertices are equal bit for bit (each patch writes its own copy).
// Vertices (position + normal) and global triangle indices stay in mapped buffers (on
// lavapipe host memory), where a renderer would bind them.
#pragma once
#include <memory>
#include <vector>

#include "realtime/patch_edges.h"
#include "geometry/patch.h"
#include "division/view_dependent.h"
#include "mesh/tessellate.h"

namespace tessera {
namespace vk {
class Context;
}
class StitchPatternRunner;  // detail/stitch_pattern_runner_vulkan.h: the pattern pipeline, buffers
class RealtimeRecorder;     // frame_record_vulkan.h: the frame recorded into an engine's commands

// How the counts are computed from a patch's screen-space net (host/division/projected.h,
// docs/realtime.md "Counts"): Estimated, the directional estimate of the grid's deviation (not
// a bound; its margin is measured: about half the triangles of Proven); Proven, the
// projected-grid bound (every inner-grid triangle within the tolerance, proven).
enum class RealtimeCounts { Estimated, Proven };

struct RealtimeOptions {
  double tolerancePixels = 1.0;
  int maxPerDirection = 64;  // counts above are clamped (reported as capped)
  // q of the split method (DivisionOptions::ratioPieces) for the patches and edges whose net
  // reaches the eye plane (viewDivisions): the pieces on which the zero- and negative-weight
  // factors are bounded.
  int ratioPieces = 4;
  // Edges are counted to this fraction of the tolerance. An edge's count bounds the chord
  // error along the edge itself, but its strip's triangles reach one inner row into the
  // patch, where the surface may curve more than on the edge (docs/realtime.md); the margin
  // keeps them within the tolerance (measured, not proven: tests/test_realtime_watertight.cpp).
  double edgeToleranceFraction = 0.25;
  RealtimeCounts counts = RealtimeCounts::Estimated;
  // Host threads for the transform, cull and counts (common/parallel_for.h; 0: all hardware
  // threads). The frame does not depend on it.
  unsigned hostThreads = 0;
};

// A frame's mesh: for each visible patch its record (counts, edge counts, first vertex and
// first index; host/realtime/detail/stitch_mirror.h gives each vertex's (u, v)), and the
// vertices and indices the GPU wrote, indices global (ready to draw).
struct RealtimeFrame {
  std::vector<gpu::StitchPatch> records;
  const gpu::GridVertex* vertices = nullptr;
  const uint32_t* indices = nullptr;
  size_t culled = 0;    // patches dropped by the frustum test or found invisible
  size_t fallback = 0;  // patches and edges whose net reaches the eye plane (viewDivisions)
  size_t capped = 0;    // patches and edges whose counts hit maxPerDirection
  size_t edges = 0;     // edges counted (collapsed ones are 1 and not counted)
  size_t triangles = 0;
  size_t countedTriangles = 0;  // Σ 2·N_u·N_v: what the patches' counts ask for
  size_t vertexCount = 0;
  size_t dispatches = 0;  // pattern submits (one per frame with a visible patch)
  // Seconds: host transform and cull (patches and edges); host counts (the projected-grid
  // bound, and viewDivisions for nets that reach the eye plane); the pattern's layout; the
  // pattern (tessellate(): upload, dispatch, fence; RealtimeRecorder::record(): recording).
  double prepareSeconds = 0, countSeconds = 0, layoutSeconds = 0, patternSeconds = 0;
};

class RealtimeTessellator {
 public:
  // The context must outlive the tessellator. Throws std::invalid_argument for a patch that
  // is not bicubic or polynomial, a tolerance ≤ 0 or maxPerDirection outside 1..256.
  RealtimeTessellator(vk::Context& context, std::vector<BezierPatch> patches,
                      const RealtimeOptions& options = {});
  ~RealtimeTessellator();

  // Tessellates the whole scene for `camera`. The frame (and the vertices and indices it
  // points to) is valid until the next call.
  const RealtimeFrame& tessellate(const Camera& camera);

  // Steps 1-2 and the pattern's layout, without the pattern (no vertices or indices yet):
  // what RealtimeRecorder records from. tessellate() is prepareFrame() then the pattern.
  const RealtimeFrame& prepareFrame(const Camera& camera);

  const std::vector<BezierPatch>& patches() const { return patches_; }

  // The last frame's pattern again, on the fp32 mirror (shaders/lib/stitch_pattern.h as C++):
  // equal to the GPU's vertices and indices bit for bit on lavapipe.
  void mirrorLastFrame(std::vector<gpu::GridVertex>& vertices,
                       std::vector<uint32_t>& indices) const;

 private:
  friend class RealtimeRecorder;
  std::vector<BezierPatch> patches_;
  std::vector<RationalBezierPatch> homogeneous_;  // weights 1, for the screen transform
  std::vector<gpu::BicubicPatch> gpuPatches_;
  PatchEdges edges_;
  std::vector<RationalBezierPatch> edgePatches_;  // edgeCountingPatch of each edge
  std::vector<glm::dvec4> screen_;                // per patch its 16 points in screen space
  RealtimeOptions options_;
  vk::Context& context_;
  std::unique_ptr<StitchPatternRunner> runner_;
  std::vector<uint32_t> items_;        // the last frame's work items: its records, in lane order
  std::vector<uint32_t> itemScratch_;  // orderBySize's second buffer
  RealtimeFrame frame_;
};

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
// The same for the tessellation-shader peer's triangles as its capture pipeline records them
// (TessShaderPeer::captureFrame, host/realtime/tess_shader_peer.h): world corners from its
// fp32 evaluation stage, (u, v) from its tessellator.
ScreenErrorReport measureScreenError(const std::vector<gpu::TessPeerTriangle>& peerTriangles,
                                     const std::vector<BezierPatch>& patches,
                                     const Camera& camera, int subdivisions = 2);

}  // namespace tessera
