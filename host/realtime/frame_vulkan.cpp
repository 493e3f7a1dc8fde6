// One frame of real-time view-dependent tessellation: cull, GPU counts, bucketed rule-A grids
// on the GPU (realtime_frame.h).
#include "realtime/frame.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "common/stopwatch.h"
#include "division/counter.h"
#include "eval/evaluator.h"
#include "geometry/rational.h"

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

}  // namespace

uint32_t gridRung(const std::vector<uint32_t>& ladder, int nu, int nv) {
  const uint32_t need = uint32_t(std::max({nu, nv, 1}));
  for (uint32_t rung : ladder)
    if (rung >= need) return rung;
  return ladder.back();  // counts are clamped to maxPerDirection, the last rung
}

RealtimeTessellator::RealtimeTessellator(vk::Context& context, std::vector<BezierPatch> patches,
                                         const RealtimeOptions& options)
    : patches_(std::move(patches)), options_(options) {
  if (!(options.tolerancePixels > 0.0))
    throw std::invalid_argument("real-time tessellation: the tolerance must be > 0 pixels");
  if (options.maxPerDirection < 1 || options.maxPerDirection > 256)
    throw std::invalid_argument("real-time tessellation: maxPerDirection must be in 1..256");
  for (size_t p = 0; p < patches_.size(); ++p)
    if (!patches_[p].weights.empty())
      throw std::invalid_argument("real-time tessellation: patch " + std::to_string(p) +
                                  " is rational; the grid evaluator takes polynomial bicubics");
  gpuPatches_ = toGpuPatches(patches_);  // refuses other degrees
  for (const BezierPatch& patch : patches_) homogeneous_.push_back(toRationalPatch(patch));
  counter_ = makeVulkanDivisionCounter(context);
  // Rungs about 1.33–1.5× apart: a grid spends at most ~2.25× the cells its counts ask for.
  for (uint32_t rung : {1u, 2u, 3u, 4u, 6u, 8u, 12u, 16u, 24u, 32u, 48u, 64u, 96u, 128u, 192u,
                        256u}) {
    if (rung >= uint32_t(options.maxPerDirection)) {
      ladder_.push_back(uint32_t(options.maxPerDirection));
      break;
    }
    ladder_.push_back(rung);
  }
  for (size_t b = 0; b < ladder_.size(); ++b)
    evaluators_.push_back(makeVulkanGridEvaluator(context));
  bucketPatches_.resize(ladder_.size());
  bucketGrids_.resize(ladder_.size());
}

RealtimeTessellator::~RealtimeTessellator() = default;

const RealtimeFrame& RealtimeTessellator::tessellate(const Camera& camera) {
  frame_ = RealtimeFrame{};
  Stopwatch stopwatch;
  std::vector<RationalBezierPatch> visible;
  std::vector<uint32_t> visibleIndex;
  for (size_t p = 0; p < patches_.size(); ++p) {
    RationalBezierPatch screen = screenSpacePatch(homogeneous_[p], camera);
    if (outsideFrustum(screen, camera)) {
      ++frame_.culled;
      continue;
    }
    visible.push_back(std::move(screen));
    visibleIndex.push_back(uint32_t(p));
  }
  const DivisionBatch batch = packDivisionBatch(visible);
  frame_.prepareSeconds = stopwatch.elapsedSeconds();

  stopwatch.restart();
  DivisionOptions counting;
  counting.tolerance = options_.tolerancePixels;
  counting.maxPerDirection = options_.maxPerDirection;
  counting.ratioPieces = options_.ratioPieces;
  const std::vector<gpu::DivisionResult> counts = counter_->count(batch, counting);
  frame_.countSeconds = stopwatch.elapsedSeconds();

  stopwatch.restart();
  for (auto& b : bucketPatches_) b.clear();
  for (auto& b : bucketGrids_) b.clear();
  for (size_t k = 0; k < visible.size(); ++k) {
    int nu = int(counts[k].nu), nv = int(counts[k].nv);
    bool capped = counts[k].status == gpu::kDivisionCapped;
    if (counts[k].status == gpu::kDivisionUnbounded) {  // the eye plane cuts the patch
      ++frame_.fallback;
      const ViewDivisions view = viewDivisions(homogeneous_[visibleIndex[k]], camera,
                                               counting);
      if (view.divisions.status == DivisionStatus::Culled || !view.divisions.bounds.visible) {
        ++frame_.culled;
        continue;
      }
      nu = view.divisions.nu;
      nv = view.divisions.nv;
      capped = view.divisions.status != DivisionStatus::Ok;
    }
    frame_.capped += capped ? 1 : 0;
    frame_.countedTriangles += 2 * size_t(nu) * size_t(nv);
    const uint32_t rung = gridRung(ladder_, nu, nv);
    const size_t b = size_t(std::find(ladder_.begin(), ladder_.end(), rung) - ladder_.begin());
    bucketGrids_[b].push_back(frame_.grids.size());
    bucketPatches_[b].push_back(gpuPatches_[visibleIndex[k]]);
    frame_.grids.push_back({visibleIndex[k], rung + 1, nu, nv, nullptr});
  }
  frame_.bucketSeconds = stopwatch.elapsedSeconds();

  stopwatch.restart();
  for (size_t b = 0; b < ladder_.size(); ++b) {
    if (bucketPatches_[b].empty()) continue;
    const uint32_t side = ladder_[b] + 1;
    const gpu::GridVertex* vertices = evaluators_[b]->evaluate(bucketPatches_[b], side);
    ++frame_.dispatches;
    for (size_t g = 0; g < bucketGrids_[b].size(); ++g)
      frame_.grids[bucketGrids_[b][g]].vertices = vertices + g * side * side;
    frame_.vertices += bucketPatches_[b].size() * side * side;
    frame_.triangles += bucketPatches_[b].size() * 2 * size_t(ladder_[b]) * ladder_[b];
  }
  frame_.gridSeconds = stopwatch.elapsedSeconds();
  return frame_;
}

}  // namespace tessera
