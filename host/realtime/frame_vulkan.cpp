// One frame of real-time view-dependent tessellation: cull and count patches and edges on the
// host, the stitched pattern on the GPU (frame.h).
#include <cstdint>  // before the generated SPIR-V array, which uses uint32_t

#include "realtime/frame.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

#include "common/parallel_for.h"
#include "common/stopwatch.h"
#include "division/projected.h"
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
bool outsideFrustum(const glm::dvec4* screen, size_t count, const Camera& camera) {
  bool left = true, right = true, top = true, bottom = true, behind = true;
  for (size_t k = 0; k < count; ++k) {
    const glm::dvec4& h = screen[k];
    left = left && h.x < 0.0;
    right = right && h.x > h.w * camera.width;
    top = top && h.y < 0.0;
    bottom = bottom && h.y > h.w * camera.height;
    behind = behind && h.w <= camera.nearW;
  }
  return left || right || top || bottom || behind;
}

// Counts of one patch or edge from its screen-space net (`screen`: a patch's 4×4 points, or an
// edge's 4 as a curve, degreeV 0) by `method` (division/projected.h), or where the net reaches
// the near plane by the host's viewDivisions of the world net (`world`), clipped to the view.
// `visible` is false when that finds it invisible.
struct Counted {
  int nu = 1, nv = 1;
  bool visible = true, capped = false, fallback = false;
};

Counted countsOf(const glm::dvec4* screen, int degreeV, const RationalBezierPatch& world,
                 const Camera& camera, RealtimeCounts method, const DivisionOptions& counting,
                 const std::array<int, 4>* sideSegments) {
  // A net that reaches the near plane: its image is unbounded or huge (the part next to the
  // eye, mostly off screen), so it is counted by the bound clipped to the view.
  const int points = 4 * (degreeV + 1);
  const bool nearEye = std::any_of(screen, screen + points,
                                   [&](const glm::dvec4& h) { return h.w <= camera.nearW; });
  const Divisions d =
      nearEye ? Divisions{0, 0, 0.0, 0.0, {}, DivisionStatus::Unbounded}
      : method == RealtimeCounts::Estimated
          ? estimatedProjectedDivisions(screen, 3, degreeV, counting.tolerance,
                                        counting.maxPerDirection, sideSegments)
          : divisionsFromBounds(projectedGridBounds(screen, 3, degreeV), counting.tolerance,
                                counting.maxPerDirection);
  Counted c;
  if (d.status != DivisionStatus::Unbounded) {
    c.nu = d.nu;
    c.nv = d.nv;
    c.capped = d.status != DivisionStatus::Ok;
    return c;
  }
  c.fallback = true;
  const ViewDivisions view = viewDivisions(world, camera, counting);
  c.visible = view.divisions.status != DivisionStatus::Culled && view.divisions.bounds.visible;
  c.nu = view.divisions.nu;
  c.nv = view.divisions.nv;
  c.capped = c.visible && view.divisions.status != DivisionStatus::Ok;
  return c;
}

// The work items ordered by their patches' (N_u, N_v): on a CPU driver neighbouring
// invocations are SIMD lanes, and a lane group runs each loop as long as its longest lane, so
// patches with equal grids side by side waste the least (bench/HISTORY.md, case 5). Two stable
// counting passes, by N_v then N_u.
void orderBySize(const std::vector<gpu::StitchPatch>& records, std::vector<uint32_t>& items,
                 std::vector<uint32_t>& scratch) {
  scratch.resize(items.size());
  uint32_t largest = 0;
  for (const gpu::StitchPatch& r : records) largest = std::max({largest, r.nu, r.nv});
  std::vector<uint32_t> starts(size_t(largest) + 2);
  auto pass = [&](const std::vector<uint32_t>& from, std::vector<uint32_t>& to, bool byU) {
    auto count = [&](uint32_t item) {
      const gpu::StitchPatch& r = records[item >> gpu::kStitchSlotBits];
      return byU ? r.nu : r.nv;
    };
    std::fill(starts.begin(), starts.end(), 0u);
    for (uint32_t item : from) ++starts[count(item) + 1];
    for (size_t k = 1; k < starts.size(); ++k) starts[k] += starts[k - 1];
    for (uint32_t item : from) to[starts[count(item)]++] = item;
  };
  pass(items, scratch, false);
  pass(scratch, items, true);
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
  const unsigned threads = options_.hostThreads;
  // Every patch to screen space and the frustum test, in parallel; then the visible ones, and
  // every edge of a visible patch, once.
  screen_.resize(16 * patches_.size());
  std::vector<uint8_t> outside(patches_.size());
  parallelFor(patches_.size(), threads, [&](size_t begin, size_t end) {
    for (size_t p = begin; p < end; ++p) {
      screenSpacePoints(homogeneous_[p].cpw.data(), 16, camera, &screen_[16 * p]);
      outside[p] = outsideFrustum(&screen_[16 * p], 16, camera);
    }
  });
  std::vector<uint32_t> visibleIndex;
  for (size_t p = 0; p < patches_.size(); ++p)
    if (outside[p])
      ++frame_.culled;
    else
      visibleIndex.push_back(uint32_t(p));
  const size_t visible = visibleIndex.size();
  std::vector<bool> edgeSeen(edgePatches_.size(), false);
  std::vector<uint32_t> countedEdges;
  for (uint32_t p : visibleIndex)
    for (uint32_t edge : edges_.sideEdge[p])
      if (!edgeSeen[edge] && !edges_.collapsed[edge]) {
        edgeSeen[edge] = true;
        countedEdges.push_back(edge);
      }
  frame_.prepareSeconds = stopwatch.elapsedSeconds();

  stopwatch.restart();
  DivisionOptions counting;
  counting.tolerance = options_.tolerancePixels;
  counting.maxPerDirection = options_.maxPerDirection;
  counting.ratioPieces = options_.ratioPieces;
  // Edge counts, from each edge's four points as a curve, to edgeToleranceFraction of the
  // tolerance; 1 for a collapsed edge, one wholly behind the near plane (its weights may even all
  // be 0; the rasterizer clips it) or one the host finds invisible.
  std::vector<uint32_t> edgeSegments(edgePatches_.size(), 1u);
  DivisionOptions edgeCounting = counting;
  edgeCounting.tolerance *= options_.edgeToleranceFraction;
  std::vector<Counted> edgeCounts(countedEdges.size());
  std::vector<uint8_t> edgeBehind(countedEdges.size());
  parallelFor(countedEdges.size(), threads, [&](size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k) {
      const uint32_t edge = countedEdges[k];
      glm::dvec4 world[4], screen[4];
      for (size_t i = 0; i < 4; ++i) world[i] = glm::dvec4(edges_.points[edge][i], 1.0);
      screenSpacePoints(world, 4, camera, screen);
      edgeBehind[k] = std::all_of(screen, screen + 4,
                                  [&](const glm::dvec4& h) { return h.w <= camera.nearW; });
      if (!edgeBehind[k])
        edgeCounts[k] = countsOf(screen, 0, edgePatches_[edge], camera, options_.counts,
                                 edgeCounting, nullptr);
    }
  });
  for (size_t k = 0; k < countedEdges.size(); ++k) {
    if (edgeBehind[k]) continue;
    ++frame_.edges;
    frame_.fallback += edgeCounts[k].fallback ? 1 : 0;
    frame_.capped += edgeCounts[k].capped ? 1 : 0;
    if (edgeCounts[k].visible) edgeSegments[countedEdges[k]] = uint32_t(std::max(edgeCounts[k].nu, 1));
  }
  // Patch counts, knowing the edge counts their strips join (a pole's 2N copies never ask for
  // fewer than N).
  // In chunks: the patches' costs differ (an estimate settles some cells early, strips are fitted
  // on some sides only), and the two halves of an even split differed by ~15 % (bench case 5).
  std::vector<Counted> patchCounts(visible);
  parallelForChunks(visible, 64, threads, [&](size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k) {
      const uint32_t p = visibleIndex[k];
      std::array<int, 4> sideSegments{};
      for (size_t side = 0; side < 4; ++side) {
        const uint32_t edge = edges_.sideEdge[p][side];
        sideSegments[side] =
            edges_.collapsed[edge] ? counting.maxPerDirection : int(edgeSegments[edge]);
      }
      patchCounts[k] = countsOf(&screen_[16 * p], 3, homogeneous_[p], camera, options_.counts,
                                counting, &sideSegments);
    }
  });
  for (const Counted& c : patchCounts) {
    frame_.fallback += c.fallback ? 1 : 0;
    frame_.capped += c.capped ? 1 : 0;
  }
  frame_.countSeconds = stopwatch.elapsedSeconds();

  stopwatch.restart();
  items_.clear();
  size_t vertexCount = 0, triangleCount = 0;
  for (size_t k = 0; k < visible; ++k) {
    const uint32_t p = visibleIndex[k];
    if (!patchCounts[k].visible) {
      ++frame_.culled;
      continue;
    }
    const int nu = patchCounts[k].nu, nv = patchCounts[k].nv;
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
    for (uint32_t band = 0; band < mirror::stitchItemCount(record); ++band)
      items_.push_back((recordIndex << gpu::kStitchSlotBits) | band);
    frame_.records.push_back(record);
  }
  orderBySize(frame_.records, items_, itemScratch_);
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
