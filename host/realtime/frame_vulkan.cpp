// One frame of real-time view-dependent tessellation: cull, GPU counts for patches and edges,
// the stitched pattern on the GPU (frame.h).
#include <cstdint>  // before the generated SPIR-V array, which uses uint32_t

#include "realtime/frame.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "common/stopwatch.h"
#include "division/counter.h"
#include "eval/evaluator.h"
#include "geometry/rational.h"
#include "realtime/detail/stitch_mirror.h"
#include "realtime/detail/stitch_pattern_runner_vulkan.h"

namespace tessera {
namespace {

// Convex-hull test in screen-space homogeneous coordinates (X, Y, ·, W): the patch is a convex
// combination of its control points there (the projection is linear before the divide), so
// if every control point is outside one half-space of the visible region 0 ≤ X ≤ W·width,
// 0 ≤ Y ≤ W·height, W > nearW, so is the patch.
bool outsideFrustum(const RationalBezierPatch& screen, const Camera& camera) {
  bool left = true, right = true, top = true, bottom = true, behind = true;
  for (const glm::dvec4& h : screen.cpw) {
    left = left && h.x < 0.0;
    right = right && h.x > h.w * camera.width;
    top = top && h.y < 0.0;
    bottom = bottom && h.y > h.w * camera.height;
    behind = behind && h.w <= camera.nearW;
  }
  return left || right || top || bottom || behind;
}

// Counts of one patch or edge from the GPU result, or from the host when the eye plane cuts
// it. Returns false when the host finds it invisible.
bool countsOf(const gpu::DivisionResult& gpuCounts, const RationalBezierPatch& world,
              const Camera& camera, const DivisionOptions& counting, int& nu, int& nv,
              bool& capped, size_t& fallback) {
  nu = int(gpuCounts.nu);
  nv = int(gpuCounts.nv);
  capped = gpuCounts.status == gpu::kDivisionCapped;
  if (gpuCounts.status != gpu::kDivisionUnbounded) return true;
  ++fallback;
  const ViewDivisions view = viewDivisions(world, camera, counting);
  if (view.divisions.status == DivisionStatus::Culled || !view.divisions.bounds.visible)
    return false;
  nu = view.divisions.nu;
  nv = view.divisions.nv;
  capped = view.divisions.status != DivisionStatus::Ok;
  return true;
}

}  // namespace

RealtimeTessellator::RealtimeTessellator(vk::Context& context, std::vector<BezierPatch> patches,
                                         const RealtimeOptions& options)
    : patches_(std::move(patches)), options_(options), context_(context) {
  if (!(options.tolerancePixels > 0.0))
    throw std::invalid_argument("real-time tessellation: the tolerance must be > 0 pixels");
  if (!(options.edgeToleranceFraction > 0.0 && options.edgeToleranceFraction <= 1.0))
    throw std::invalid_argument("real-time tessellation: edgeToleranceFraction must be in (0, 1]");
  if (options.maxPerDirection < 1 || options.maxPerDirection > 256)
    throw std::invalid_argument("real-time tessellation: maxPerDirection must be in 1..256");
  if (patches_.size() >= (size_t(1) << (32 - gpu::kStitchSlotBits)))
    throw std::invalid_argument("real-time tessellation: at most " +
                                std::to_string((1u << (32 - gpu::kStitchSlotBits)) - 1) +
                                " patches, got " + std::to_string(patches_.size()));
  for (size_t p = 0; p < patches_.size(); ++p)
    if (!patches_[p].weights.empty())
      throw std::invalid_argument("real-time tessellation: patch " + std::to_string(p) +
                                  " is rational; the pattern evaluates polynomial bicubics");
  gpuPatches_ = toGpuPatches(patches_);  // refuses other degrees
  for (const BezierPatch& patch : patches_) homogeneous_.push_back(toRationalPatch(patch));
  edges_ = findPatchEdges(patches_);
  for (const auto& edge : edges_.points) edgePatches_.push_back(edgeCountingPatch(edge));
  counter_ = makeVulkanDivisionCounter(context);
  runner_ = std::make_unique<StitchPatternRunner>(context, gpuPatches_, edges_.gpuPoints);
}

RealtimeTessellator::~RealtimeTessellator() = default;

const RealtimeFrame& RealtimeTessellator::tessellate(const Camera& camera) {
  prepareFrame(camera);
  Stopwatch stopwatch;
  if (!frame_.records.empty()) {
    runner_->run(frame_.records, items_, frame_.vertexCount, 3 * frame_.triangles);
    frame_.vertices = runner_->vertices();
    frame_.indices = runner_->indices();
    ++frame_.dispatches;
  }
  frame_.patternSeconds = stopwatch.elapsedSeconds();
  return frame_;
}

const RealtimeFrame& RealtimeTessellator::prepareFrame(const Camera& camera) {
  frame_ = RealtimeFrame{};
  Stopwatch stopwatch;
  // The batch: visible patches first, then every edge of a visible patch, once.
  std::vector<RationalBezierPatch> batchPatches;
  std::vector<uint32_t> visibleIndex;
  for (size_t p = 0; p < patches_.size(); ++p) {
    RationalBezierPatch screen = screenSpacePatch(homogeneous_[p], camera);
    if (outsideFrustum(screen, camera)) {
      ++frame_.culled;
      continue;
    }
    batchPatches.push_back(std::move(screen));
    visibleIndex.push_back(uint32_t(p));
  }
  const size_t visible = visibleIndex.size();
  std::vector<int64_t> edgeSlot(edgePatches_.size(), -1);  // batch entry of a counted edge
  std::vector<uint32_t> countedEdges;
  std::vector<RationalBezierCurve> edgeCurves;
  for (uint32_t p : visibleIndex)
    for (uint32_t edge : edges_.sideEdge[p])
      if (edgeSlot[edge] == -1 && !edges_.collapsed[edge]) {
        edgeSlot[edge] = -2;  // seen
        // The counting patch's first row, in screen space; wholly behind the near plane (its
        // weights may even all be 0): 1, the rasterizer clips it.
        const RationalBezierPatch screen = screenSpacePatch(edgePatches_[edge], camera);
        RationalBezierCurve curve;
        bool behind = true;
        for (int i = 0; i <= 3; ++i) {
          glm::dvec4 h = screen.at(i, 0);
          behind = behind && h.w <= camera.nearW;
          // Pixels scaled by 1/fraction: the batch's tolerance then counts the edge to
          // fraction · tolerance (second derivatives scale with the coordinates).
          h.x /= options_.edgeToleranceFraction;
          h.y /= options_.edgeToleranceFraction;
          curve.cpw.push_back(h);
        }
        if (behind) continue;
        edgeSlot[edge] = int64_t(visible + edgeCurves.size());
        edgeCurves.push_back(std::move(curve));
        countedEdges.push_back(edge);
      }
  frame_.edges = countedEdges.size();
  DivisionBatch batch = packDivisionBatch(batchPatches);
  appendDivisionCurves(batch, edgeCurves);
  frame_.prepareSeconds = stopwatch.elapsedSeconds();

  stopwatch.restart();
  DivisionOptions counting;
  counting.tolerance = options_.tolerancePixels;
  counting.maxPerDirection = options_.maxPerDirection;
  counting.ratioPieces = options_.ratioPieces;
  const std::vector<gpu::DivisionResult> counts = counter_->count(batch, counting);
  frame_.countSeconds = stopwatch.elapsedSeconds();

  stopwatch.restart();
  // Edge counts: N_u of the edge's counting patch; 1 for a collapsed edge or one the host finds
  // invisible (behind the near plane: the rasterizer clips it).
  std::vector<uint32_t> edgeSegments(edgePatches_.size(), 1u);
  DivisionOptions edgeCounting = counting;
  edgeCounting.tolerance *= options_.edgeToleranceFraction;
  for (uint32_t edge : countedEdges) {
    int nu = 1, nv = 1;
    bool capped = false;
    if (countsOf(counts[size_t(edgeSlot[edge])], edgePatches_[edge], camera, edgeCounting, nu, nv,
                 capped, frame_.fallback))
      edgeSegments[edge] = uint32_t(std::max(nu, 1));
    frame_.capped += capped ? 1 : 0;
  }
  items_.clear();
  sideItems_.clear();
  size_t vertexCount = 0, triangleCount = 0;
  for (size_t k = 0; k < visible; ++k) {
    const uint32_t p = visibleIndex[k];
    int nu = 1, nv = 1;
    bool capped = false;
    if (!countsOf(counts[k], homogeneous_[p], camera, counting, nu, nv, capped,
                  frame_.fallback)) {
      ++frame_.culled;
      continue;
    }
    frame_.capped += capped ? 1 : 0;
    frame_.countedTriangles += 2 * size_t(nu) * size_t(nv);
    gpu::StitchPatch record{};
    record.patchIndex = p;
    record.nu = uint32_t(std::max(nu, 1));
    record.nv = uint32_t(std::max(nv, 1));
    for (int s = 0; s < 4; ++s) {
      record.sideEdge[s] = edges_.sideEdge[p][s];
      record.sideFlags[s] = edges_.sideFlags[p][s];
      // A pole shares no edge: 2n copies of it put one in the middle of each inner segment
      // of the fan (stitchAdvanceOuter), so every fan triangle's (u, v) hugs its own part of
      // the side (the copies are equal points: no triangle is drawn along the side).
      record.sideSegments[s] = edges_.collapsed[edges_.sideEdge[p][s]]
                                   ? 2 * ((s & 1) == 0 ? record.nu : record.nv)
                                   : edgeSegments[edges_.sideEdge[p][s]];
    }
    record.firstVertex = uint32_t(vertexCount);
    record.firstIndex = uint32_t(3 * triangleCount);
    vertexCount += mirror::stitchVertexCount(record);
    triangleCount += mirror::stitchTriangleCount(record);
    const uint32_t recordIndex = uint32_t(frame_.records.size());
    const uint32_t rows = mirror::stitchItemCount(record) - 4;
    for (uint32_t slot = 0; slot < rows + 4; ++slot)
      (slot < rows ? items_ : sideItems_).push_back((recordIndex << gpu::kStitchSlotBits) | slot);
    frame_.records.push_back(record);
  }
  // Rows first, then sides: neighbouring invocations (SIMD lanes) run the same branch.
  items_.insert(items_.end(), sideItems_.begin(), sideItems_.end());
  if (3 * triangleCount > UINT32_MAX || vertexCount > UINT32_MAX)
    throw std::length_error("real-time tessellation: a frame of " + std::to_string(triangleCount) +
                            " triangles exceeds 32-bit indices");
  frame_.vertexCount = vertexCount;
  frame_.triangles = triangleCount;
  frame_.layoutSeconds = stopwatch.elapsedSeconds();
  return frame_;
}

void RealtimeTessellator::mirrorLastFrame(std::vector<gpu::GridVertex>& vertices,
                                          std::vector<uint32_t>& indices) const {
  vertices.assign(frame_.vertexCount, gpu::GridVertex{});
  indices.assign(3 * frame_.triangles, 0u);
  for (uint32_t item : items_)
    mirror::stitchItem(gpuPatches_.data(), frame_.records.data(), edges_.gpuPoints.data(), item,
                       kDegenerateEpsFp32, vertices.data(), indices.data());
}

}  // namespace tessera
