#include "mesh/screen_tolerance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "common/stopwatch.h"
#include "geometry/general_patch.h"
#include "geometry/homogeneous_net.h"
#include "geometry/rational.h"
#include "quadtree/revising_classifier.h"

namespace tessera {
namespace {

// Where a node's surface lies against the view volume.
enum class Visibility { Inside, Culled, NearPlane };

// The six clip planes of Vulkan's view volume as linear functionals of a homogeneous clip
// point h: visible where every f(h) ≥ 0 (−W ≤ x, y ≤ W, 0 ≤ z ≤ W). A surface point is
// Σ B_ij h_ij / Σ B_ij w_ij with Σ B_ij w_ij > 0 (weights ≥ 0, corner weights > 0), so
// f(point) has the sign of Σ B_ij f(h_ij): every f(h_ij) < 0 puts the whole node outside.
constexpr int kPlanes = 6;
constexpr int kNearPlane = 4;  // z ≥ 0
double planeValue(int plane, const glm::dvec4& h) {
  switch (plane) {
    case 0: return h.w + h.x;
    case 1: return h.w - h.x;
    case 2: return h.w + h.y;
    case 3: return h.w - h.y;
    case kNearPlane: return h.z;
    default: return h.w - h.z;
  }
}

Visibility visibilityOf(const HomogeneousNet& clip) {
  std::array<bool, kPlanes> allOutside, allInside;
  allOutside.fill(true);
  allInside.fill(true);
  for (const glm::dvec4& h : clip.c)
    for (int k = 0; k < kPlanes; ++k) {
      const double f = planeValue(k, h);
      allOutside[k] = allOutside[k] && f < 0.0;
      allInside[k] = allInside[k] && f >= 0.0;
    }
  for (bool out : allOutside)
    if (out) return Visibility::Culled;
  return allInside[kNearPlane] ? Visibility::Inside : Visibility::NearPlane;
}

// Culled nodes above this level split both ways, so a culled patch keeps at least 2^k × 2^k
// cells: with fewer, a patch's side may become one chord that other patches' sides share too
// (the teapot's handle: two half-tubes with the same four corners, whose one-segment sides
// would make one edge of four triangles).
constexpr uint32_t kCulledMinLevel = 1;

bool wholeNetInside(const HomogeneousNet& clip) {
  for (const glm::dvec4& h : clip.c)
    for (int k = 0; k < kPlanes; ++k)
      if (!(planeValue(k, h) >= 0.0)) return false;
  return true;
}

class ScreenSpaceClassifier final : public RevisingClassifier {
 public:
  ScreenSpaceClassifier(NodeClassifier& inner, const std::vector<BezierPatch>& patches,
                        const Camera& camera, uint32_t eyePlaneDepth)
      : RevisingClassifier(inner, patches.size()), eyePlaneDepth_(eyePlaneDepth) {
    clipNets_.reserve(patches.size());
    needsTest_.reserve(patches.size());
    for (const BezierPatch& p : patches) {
      HomogeneousNet net = toNet(toRationalPatch(p));
      for (glm::dvec4& h : net.c) h = camera.viewProjection * h;
      needsTest_.push_back(!wholeNetInside(net));
      clipNets_.push_back(std::move(net));
    }
  }

  std::string name() const override { return inner().name() + " (screen space)"; }

 private:
  void revise(const std::vector<gpu::QuadNode>& nodes, const QuadtreeOptions&,
              std::vector<gpu::NodeDecision>& decisions, LevelStats& stats) override {
    const Stopwatch stopwatch;
    for (size_t i = 0; i < nodes.size(); ++i) {
      const gpu::QuadNode& n = nodes[i];
      const size_t patch = groupFirst() + n.patchIndex;
      if (!needsTest_[patch]) continue;
      const HomogeneousNet sub = subNet(clipNets_[patch], n.rect.x, n.rect.z, n.rect.y, n.rect.w);
      gpu::NodeDecision& d = decisions[i];
      switch (visibilityOf(sub)) {
        case Visibility::Inside: break;
        case Visibility::Culled:  // unseen: no bound to keep (the inner one may be NaN)
          d.cause = n.level >= kCulledMinLevel ? gpu::kCauseCulled : gpu::kCauseSplit;
          d.flatness = 0.0f;
          break;
        case Visibility::NearPlane:
          if (d.cause == gpu::kCauseWithinTolerance) break;  // proven where W > 0 throughout
          if (n.level >= eyePlaneDepth_) d.cause = gpu::kCauseEyePlane;
          break;
      }
      // The fan apex of a leaf, the split point of a split: the centre (rule T's own).
      d.split.x = 0.5f * (n.rect.x + n.rect.z);
      d.split.y = 0.5f * (n.rect.y + n.rect.w);
    }
    stats.classifyMs += stopwatch.elapsedMs();
  }

  uint32_t eyePlaneDepth_;
  std::vector<HomogeneousNet> clipNets_;  // each patch's homogeneous net in clip space
  std::vector<bool> needsTest_;           // false: the whole net is inside the view volume
};

}  // namespace

PatchSet screenSpacePatchSet(const std::vector<BezierPatch>& patches, const Camera& camera) {
  GeneralPatchSet set;
  set.patches.reserve(patches.size());
  for (const BezierPatch& p : patches) {
    set.patches.push_back(
        {uint32_t(p.degreeU), uint32_t(p.degreeV), 1u, uint32_t(set.points.size())});
    for (const glm::dvec4& h : screenSpacePatch(toRationalPatch(p), camera).cpw)
      set.points.push_back(gpu::vec4(h));
  }
  return PatchSet(std::move(set));
}

std::unique_ptr<NodeClassifier> makeScreenSpaceClassifier(NodeClassifier& inner,
                                                          const std::vector<BezierPatch>& patches,
                                                          const Camera& camera,
                                                          uint32_t eyePlaneDepth) {
  return std::make_unique<ScreenSpaceClassifier>(inner, patches, camera, eyePlaneDepth);
}

void validateScreenView(const ScreenView& view, const QuadtreeOptions& options) {
  if (view.camera.width < 1 || view.camera.height < 1)
    throw std::invalid_argument("pixel tolerance: the viewport must be at least 1×1 pixels");
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(view.camera.viewProjection[c][r]))
        throw std::invalid_argument("pixel tolerance: the view-projection matrix is not finite");
  if (options.rule != SplitRule::Tolerance)
    throw std::invalid_argument("pixel tolerance: the quad-tree must run rule T");
  if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance))
    throw std::invalid_argument("pixel tolerance: δ must be finite and > 0 pixels");
}

Tessellation tessellateScreenTolerance(const std::vector<BezierPatch>& patches,
                                       const QuadtreeOptions& options, const ScreenView& view,
                                       Backend& backend) {
  const Stopwatch total;
  validateScreenView(view, options);
  for (size_t i = 0; i < patches.size(); ++i)
    validateTessellationPatch(patches[i], "patch " + std::to_string(i));
  const Stopwatch treeStep;
  const PatchSet screen = screenSpacePatchSet(patches, view.camera);
  // The tree is in pixels; the mesh is evaluated and welded in the model's local frame.
  const ModelFrame frame = modelFrame(patches);
  std::vector<BezierPatch> local = toLocalFrame(patches, frame);
  PatchSet world = toPatchSet(local);
  backend.evaluator->prepareVertices(world);
  const std::unique_ptr<NodeClassifier> classifier =
      makeScreenSpaceClassifier(*backend.classifier, patches, view.camera, view.eyePlaneDepth);
  QuadtreeResult tree = buildQuadtree(screen, options, *classifier);
  const double treeMs = treeStep.elapsedMs();
  Tessellation result =
      meshFromTree(std::move(local), std::move(world), std::move(tree), *backend.evaluator, frame);
  result.stats.treeMs = treeMs;
  result.stats.totalMs = total.elapsedMs();
  return result;
}

ScreenLeafCounts screenLeafCounts(const QuadtreeResult& tree) {
  ScreenLeafCounts counts;
  for (const QuadLeaf& leaf : tree.leaves) {
    if (leaf.cause == gpu::kCauseCulled) {
      ++counts.culled;
      continue;
    }
    if (leaf.cause == gpu::kCauseEyePlane) {
      ++counts.eyePlane;
      continue;
    }
    ++(leaf.cause == gpu::kCauseWithinTolerance ? counts.proven : counts.other);
    const double bound =
        std::isnan(leaf.flatness) ? INFINITY : double(leaf.flatness) * tree.boundScale;
    counts.largestBound = std::max(counts.largestBound, bound);
  }
  return counts;
}

}  // namespace tessera
