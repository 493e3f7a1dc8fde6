// Rule T on surfaces of revolution by the distance to the surface (docs/trimmed_faces.md, "A
// geometric bound on surfaces of revolution"). Rule T's own bound is parametric: it holds a
// triangle point against S at the same (u, v) mix, and on the rational pieces of a circle
// (not parametrised by angle) it counts the sliding along the surface as error. The distance to
// the surface (the measure, and OCCT's deflection) has a bound that depends on the
// node's angles only: for every point of the convex hull of a node's patch (so of every
// triangle whose corners lie on the node),
//
//   distance ≤ ρ_max·(1 − cos α) + r·(1 − cos β)
//
// with α half the node's azimuth span, ρ_max the largest distance from the axis over the node,
// β half the node's span along a circular profile of radius r (0 for a line: cylinder, cone).
#pragma once
#include <memory>
#include <vector>

#include "quadtree/quadtree.h"
#include "trim/face_surface.h"
#include "quadtree/revising_classifier.h"
#include "trim/trimmed_face.h"

namespace tessera {

// The bound's two terms, model units: azimuth ρ_max·(1 − cos α) (split u), profile r·(1 − cos β)
// (split v). valid is false where the node's spans are not known to be under π/2 (an angle
// measured between corners is then not the span), and the node must split.
struct RevolutionBound {
  double azimuth = 0.0, profile = 0.0;
  double guard = 0.0;  // the pieces' conversion rounding, 10⁻¹² of the node's size from the origin
  bool valid = false;
};

// `rect` is the node in piece `piece`'s local [0,1]² (a QuadNode's rect).
RevolutionBound revolutionNodeBound(const RevolutionForm& form, const FaceSurface& surface,
                                    size_t piece, glm::dvec4 rect);

// A NodeClassifier decorator: nodes of a patch with a known form are decided by the bound above
// (rule T's decision text, lib/tolerance_bound.h's toleranceDecision, fed the two terms as its
// u and v parts), the others keep `inner`'s decision. Patch k of the tree (over all patch groups
// of buildQuadtree, in order) is `pieces[k]` of `faces[k]`; a null form keeps inner's decision.
class RevolutionBoundClassifier final : public RevisingClassifier {
 public:
  struct Patch {
    const RevolutionForm* form = nullptr;  // null or Profile::None: rule T's own decision
    const FaceSurface* surface = nullptr;
    size_t piece = 0;
  };
  // The tree works in a local frame (geometry/model_frame.h): model = local·scale + centre, so
  // its tolerance is δ/scale and the bound, found in model units, is divided by `scale` too.
  // A batch's bounds are found on `threads` threads (0: all cores).
  RevolutionBoundClassifier(NodeClassifier& inner, std::vector<Patch> patches, double scale,
                            unsigned threads = 0);

  std::string name() const override;
  size_t decided() const { return decided_; }  // nodes decided by the distance bound

 private:
  void revise(const std::vector<gpu::QuadNode>& nodes, const QuadtreeOptions& options,
              std::vector<gpu::NodeDecision>& decisions, LevelStats& stats) override;
  // A known form's nodes under rule T: revise() sets their decisions from the bound alone, so
  // the inner (rule T's parametric) classifier never decides them.
  bool rewritesWhole(size_t patch, const QuadtreeOptions& options) const override;

  std::vector<Patch> patches_;
  double scale_;
  unsigned threads_;
  size_t decided_ = 0;
  std::vector<size_t> revised_;  // the batch's nodes revise() decides
};

}  // namespace tessera
