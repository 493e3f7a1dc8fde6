// Rule T with δ in pixels: the same quad-tree and classifier, run on the patches as a camera
// sees them. Each patch's control points go to screen-space homogeneous coordinates
// (x_px·W, y_px·W, 0, W) (screenSpacePatch, division/view_dependent.h), a rational patch whose
// projection is the patch's image in pixels; rule T on that set bounds, per leaf, how far each
// drawn triangle lies from the projected surface, in pixels. The mesh is then made and
// evaluated from the ORIGINAL patches on the same leaves: model-space positions, watertight by
// the leaf triangulator, and each triangle's projection within δ px (docs/quadtree.md,
// "Rule T in screen space").
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "division/view_dependent.h"
#include "mesh/tessellate.h"

namespace tessera {

// Nodes the near plane cuts split (as the classifier says, or both ways) down to this level,
// then end as kCauseEyePlane leaves: their triangles are partly clipped when drawn and outside
// the proof, and splitting on towards the near-plane curve would cost 2^level nodes.
constexpr uint32_t kDefaultEyePlaneDepth = 10;

// The camera of a pixel tolerance (QuadtreeOptions::tolerance then counts pixels).
struct ScreenView {
  Camera camera;
  uint32_t eyePlaneDepth = kDefaultEyePlaneDepth;
};

// The screen-space set the classifier sees: every patch rational (weights W·w), z = 0, in the
// general layout. Weights may be ≤ 0 where a patch reaches the eye plane; the classifier's
// answer for such nodes is replaced (makeScreenSpaceClassifier).
PatchSet screenSpacePatchSet(const std::vector<BezierPatch>& patches, const Camera& camera);

// Wraps `inner` (mirror, reference or Vulkan: it decides every node, so GPU = mirror bit for
// bit stands) and overrides, from the node's clip-space net restricted to its rectangle in
// double: a node whose hull lies outside one clip plane (x = ±W, y = ±W, z = 0, z = W) →
// kCauseCulled leaf (split both ways at level 0 first, so no patch is two triangles); one the
// near plane cuts → the inner split, or a kCauseEyePlane leaf at
// level ≥ eyePlaneDepth (an inner WithinTolerance leaf is kept: its bound is proven). Patches
// whose whole net is inside every plane skip the test. `inner` must outlive the wrapper; the
// wrapper follows buildQuadtree's patch groups (consecutive beginTree calls), so it serves one
// buildQuadtree call.
std::unique_ptr<NodeClassifier> makeScreenSpaceClassifier(NodeClassifier& inner,
                                                          const std::vector<BezierPatch>& patches,
                                                          const Camera& camera,
                                                          uint32_t eyePlaneDepth);

// Throws std::invalid_argument for a viewport < 1 px, a matrix that is not finite, or
// options that are not rule T with a finite tolerance > 0.
void validateScreenView(const ScreenView& view, const QuadtreeOptions& options);

// The whole job: validate the patches (validateTessellationPatch), build the screen-space
// tree on backend.classifier, mesh and evaluate the original patches on its leaves.
// Leaves' causes tell culled (kCauseCulled) and eye-plane (kCauseEyePlane) ones apart; culled
// leaves still emit their (off-screen) triangles, so a closed model stays closed.
// options: rule T, tolerance = δ in pixels (toleranceOptions(δ) gives the depth limit).
Tessellation tessellateScreenTolerance(const std::vector<BezierPatch>& patches,
                                       const QuadtreeOptions& options, const ScreenView& view,
                                       Backend& backend);

// A screen-space tree's leaves by cause: proven (kCauseWithinTolerance), culled, cut by the
// near plane, and others (MaxDepth, MinSize: in view, bound above δ). largestBound is the
// largest bound (pixels) over the leaves in view, proven and others (a bound that is not a
// number counts as infinite): the mesh in view is proven within it.
struct ScreenLeafCounts {
  size_t proven = 0, culled = 0, eyePlane = 0, other = 0;
  double largestBound = 0;
};
ScreenLeafCounts screenLeafCounts(const QuadtreeResult& tree);

}  // namespace tessera
